#include "export/plot_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "export/csv_writer.hpp"
#include "export/pdf_writer.hpp"
#include "export/svg_writer.hpp"

namespace stipple::plot {

namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

bool is_plot_path(const std::string& path) {
    const std::string ext = extension_of(path);
    return ext == ".svg" || ext == ".pdf" || ext == ".csv";
}

bool is_svg_path(const std::string& path) { return extension_of(path) == ".svg"; }
bool is_png_path(const std::string& path) { return extension_of(path) == ".png"; }
bool is_csv_path(const std::string& path) { return extension_of(path) == ".csv"; }

void check_page_for_format(const std::string& path, double width_mm, double height_mm) {
    if (extension_of(path) == ".pdf" && std::max(width_mm, height_mm) > kPdfMaxPageMm)
        fail_file(path, "a PDF page is at most 5080 mm (200 in) a side, and this page is " + std::to_string(std::lround(width_mm)) +
                            " x " + std::to_string(std::lround(height_mm)) + " mm: write an SVG (.svg) or choose a smaller --page");
}

void write_plot_file(const PlotPlan& plan, const std::string& path) {
    const std::string ext = extension_of(path);
    check_page_for_format(path, plan.layout.page.width_mm, plan.layout.page.height_mm);
    // Each writer writes through write_output (io/output_file.hpp): into a folder made if missing, as PNG
    // images are, whole or not at all, and the file tried first for the cause of a failure.
    if (ext == ".svg") write_svg(plan, path);
    else if (ext == ".pdf") write_pdf(plan, path);
    else if (ext == ".csv") write_csv(plan, path);
    else fail_file(path, "unknown drawing format '" + ext + "' (expected .svg, .pdf or .csv)");
}

}  // namespace stipple::plot
