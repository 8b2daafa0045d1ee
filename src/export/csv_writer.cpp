#include "export/csv_writer.hpp"

#include "export/text_format.hpp"

namespace stipple::plot {

std::string csv_document(const PlotPlan& plan) {
    std::string out = "x_mm,y_mm,radius_mm,object,polygon\n";
    // To 0.001 mm, or finer where a pixel is small on the page (as the SVG writes them).
    const int position = decimals_for(plan.layout.mm_per_px, 1.0 / 10.0, 3), radius = decimals_for(plan.layout.mm_per_px, 1.0 / 100.0, 3);
    for (const PlotLayer& layer : plan.layers)
        for (const PlotDot& dot : layer.dots) {
            append_number(out, dot.mm.x, position);
            out += ',';
            append_number(out, dot.mm.y, position);
            out += ',';
            append_number(out, dot.radius_mm, radius);
            out += ',';
            out += std::to_string(dot.object);
            out += ',';
            out += std::to_string(dot.polygon);
            out += '\n';
        }
    return out;
}

void write_csv(const PlotPlan& plan, const std::string& path) { write_text_file(path, csv_document(plan)); }

}  // namespace stipple::plot
