#pragma once
// The paper's Table 1 (Lu et al., VMV 2002: 1280x1024, GeForce3 Ti 500) and the benchmark's columns:
// every density path, without and with Raskar-Cohen silhouette lines.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "params/object_params.hpp"

namespace stipple::bench {

// One row of Table 1: the model, its polygon count and the four frame rates (fps).
struct PaperRow {
    const char* name;
    uint32_t polygons;
    double vertex;        // stipple only, vertex program
    double cpu;           // stipple only, no vertex program
    double vertex_lines;  // stipple & silhouette, vertex program
    double cpu_lines;     // stipple & silhouette, no vertex program
};

inline constexpr std::array<PaperRow, 7> kPaperTable{{
    {"horse", 13'352, 60.39, 60.39, 30.19, 30.19},
    {"low-res dragon", 45'106, 32.05, 30.4, 15.60, 15.24},
    {"bunny", 69'451, 30.12, 20.07, 12.03, 11.89},
    {"skeleton1", 124'018, 20.66, 12.08, 10.16, 7.53},
    {"skeleton2", 522'567, 4.65, 2.60, 1.94, 1.50},
    {"hand", 654'666, 4.00, 2.07, 1.88, 1.32},
    {"dragon", 871'414, 2.99, 1.50, 1.32, 0.91},
}};

// The row named `name`, or nullptr.
const PaperRow* find_paper_row(const std::string& name);
// Names of all rows, comma separated, spaces as hyphens (for messages).
std::string paper_row_names();

// Beyond the paper: one kind of object-space line per column (ObjectParams::contours, borders, creases).
enum class ObjectLines { None, Contours, Borders, Creases };
const char* object_lines_name(ObjectLines lines);  // "none", "contours", "borders", "creases"

// A column of our table: a density path, without or with Raskar-Cohen lines (§3.1), or with one kind
// of object-space line instead.
struct Column {
    DensityPath path = DensityPath::Vertex;
    bool lines = false;  // the paper's silhouettes (Raskar-Cohen)
    ObjectLines object_lines = ObjectLines::None;

    std::string name() const;  // "vertex", "vertex + lines", "vertex + contours"
    bool operator==(const Column&) const = default;
};

// The paper's figure for the matching column (none for object-space lines, which it does not have).
// The paper's columns say where the density is computed:
// "vertex program" on the GPU (our vertex, indirect and splat paths), "no vertex program" on the CPU
// (our cpu and cpu-splat paths). How the stipples are then drawn is ours to choose.
std::optional<double> paper_fps(const PaperRow& row, const Column& column);
// The paper's column title for our column.
std::string paper_column_name(const Column& column);

// The columns for these paths: each path without lines, then each with lines, then (with
// `object_lines`) each with contours, with borders and with creases.
std::vector<Column> make_columns(const std::vector<DensityPath>& paths, bool object_lines = false);

// Every density path the renderer has (kAllDensityPaths), in its order.
std::vector<DensityPath> all_density_paths();

}  // namespace stipple::bench
