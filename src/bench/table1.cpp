#include "bench/table1.hpp"

#include <algorithm>

namespace stipple::bench {

const PaperRow* find_paper_row(const std::string& name) {
    // "low-res-dragon" too, as the row's model and image files are named (no quotes needed in a shell).
    for (const PaperRow& row : kPaperTable) {
        std::string hyphened = row.name;
        std::replace(hyphened.begin(), hyphened.end(), ' ', '-');
        if (name == row.name || name == hyphened) return &row;
    }
    return nullptr;
}

std::string paper_row_names() {
    std::string names;
    for (const PaperRow& row : kPaperTable) {  // as a shell takes them without quotes (and bench --help lists them)
        std::string hyphened = row.name;
        std::replace(hyphened.begin(), hyphened.end(), ' ', '-');
        names += (names.empty() ? "" : ", ") + hyphened;
    }
    return names;
}

const char* object_lines_name(ObjectLines lines) {
    switch (lines) {
        case ObjectLines::None: return "none";
        case ObjectLines::Contours: return "contours";
        case ObjectLines::Borders: return "borders";
        case ObjectLines::Creases: break;
    }
    return "creases";
}

std::string Column::name() const {
    std::string name = density_path_name(path);
    if (lines) name += " + lines";
    if (object_lines != ObjectLines::None) name += std::string(" + ") + object_lines_name(object_lines);
    return name;
}

std::optional<double> paper_fps(const PaperRow& row, const Column& column) {
    if (column.object_lines != ObjectLines::None) return std::nullopt;
    if (density_on_cpu(column.path)) return column.lines ? row.cpu_lines : row.cpu;
    return column.lines ? row.vertex_lines : row.vertex;
}

std::string paper_column_name(const Column& column) {
    const std::string program = density_on_cpu(column.path) ? "no vertex program" : "vertex program";
    return (column.lines ? "stipple & silhouette, " : "stipple only, ") + program;
}

std::vector<Column> make_columns(const std::vector<DensityPath>& paths, bool object_lines) {
    std::vector<Column> columns;
    for (bool lines : {false, true})
        for (DensityPath path : paths) columns.push_back({path, lines});
    if (object_lines)
        for (ObjectLines kind : {ObjectLines::Contours, ObjectLines::Borders, ObjectLines::Creases})
            for (DensityPath path : paths) columns.push_back({path, false, kind});
    return columns;
}

std::vector<DensityPath> all_density_paths() {
    return std::vector<DensityPath>(std::begin(kAllDensityPaths), std::end(kAllDensityPaths));
}

}  // namespace stipple::bench
