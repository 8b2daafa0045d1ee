#include "bench/table1.hpp"

namespace stipple::bench {

const PaperRow* find_paper_row(const std::string& name) {
    for (const PaperRow& row : kPaperTable)
        if (name == row.name) return &row;
    return nullptr;
}

std::string paper_row_names() {
    std::string names;
    for (const PaperRow& row : kPaperTable) names += std::string(names.empty() ? "" : ", ") + row.name;
    return names;
}

std::string Column::name() const { return std::string(density_path_name(path)) + (lines ? " + lines" : ""); }

std::optional<double> paper_fps(const PaperRow& row, const Column& column) {
    if (density_on_cpu(column.path)) return column.lines ? row.cpu_lines : row.cpu;
    return column.lines ? row.vertex_lines : row.vertex;
}

std::string paper_column_name(const Column& column) {
    const std::string program = density_on_cpu(column.path) ? "no vertex program" : "vertex program";
    return (column.lines ? "stipple & silhouette, " : "stipple only, ") + program;
}

std::vector<Column> make_columns(const std::vector<DensityPath>& paths) {
    std::vector<Column> columns;
    for (bool lines : {false, true})
        for (DensityPath path : paths) columns.push_back({path, lines});
    return columns;
}

std::vector<DensityPath> all_density_paths() {
    return std::vector<DensityPath>(std::begin(kAllDensityPaths), std::end(kAllDensityPaths));
}

}  // namespace stipple::bench
