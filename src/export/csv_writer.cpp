#include "export/csv_writer.hpp"

#include "export/text_format.hpp"

namespace stipple::plot {

std::string csv_document(const PlotPlan& plan) {
    std::string out = "x_mm,y_mm,radius_mm,object,polygon\n";
    for (const PlotLayer& layer : plan.layers)
        for (const PlotDot& dot : layer.dots) {
            append_number(out, dot.mm.x, 3);
            out += ',';
            append_number(out, dot.mm.y, 3);
            out += ',';
            append_number(out, dot.radius_mm, 3);
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
