#include "export/svg_writer.hpp"

#include <algorithm>
#include <cmath>

#include "core/printf_string.hpp"
#include "export/text_format.hpp"

namespace stipple::plot {

namespace {

// Decimals of millimetres: coordinates to 0.01 mm (finer than any pen) and radii to 0.001 mm (a faded dot's
// radius is small), or finer where a pixel of the image is small on the page (plot::decimals_for): on a page
// of 12.5 mm every radius was one of 8 values and 7% of the ink was lost.
struct Places {
    int position = 2;
    int radius = 3;
};
constexpr size_t kTicksPerPath = 1000;

void append_layer_open(std::string& out, const PlotLayer& layer, const std::string& style) {
    out += "<g inkscape:groupmode=\"layer\" id=\"layer";
    out += std::to_string(layer.number);
    out += "\" inkscape:label=\"";
    out += xml_escape(layer.label);
    out += "\" ";
    out += style;
    out += ">\n";
}

// A stroke's width to 0.001 mm, and to three significant digits below 0.1 mm: a 0.0004 mm pen written to
// 0.001 mm was stroke-width="0", and every circle and tick vanished. SVG reads "1e-05" as a number too.
std::string stroke_width(double mm) {
    return mm >= 0.1 ? format_number(mm, 3) : printf_string("%.3g", mm);
}

std::string stroke_style(const std::string& ink, double width_mm) {
    return "fill=\"none\" stroke=\"" + ink + "\" stroke-width=\"" + stroke_width(width_mm) +
           "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
}

void append_dots(std::string& out, const PlotLayer& layer, DotStyle style, const std::string& ink, Places places) {
    if (style == DotStyle::Tick) {
        append_layer_open(out, layer, stroke_style(ink, layer.stroke_mm));
        for (size_t i = 0; i < layer.dots.size(); ++i) {
            if (i % kTicksPerPath == 0) out += i == 0 ? "<path d=\"" : "\"/>\n<path d=\"";
            const std::array<glm::dvec2, 2> ends = dot_stroke_ends(layer.dots[i], style, layer.stroke_mm);
            out += 'M';
            append_number(out, ends[0].x, places.position);
            out += ' ';
            append_number(out, ends[0].y, places.position);
            out += 'h';
            append_number(out, ends[1].x - ends[0].x, places.position);
            out += '\n';
        }
        if (!layer.dots.empty()) out += "\"/>\n";
        out += "</g>\n";
        return;
    }
    append_layer_open(out, layer, style == DotStyle::Filled ? "fill=\"" + ink + "\" stroke=\"none\"" : stroke_style(ink, layer.stroke_mm));
    for (const PlotDot& dot : layer.dots) {
        out += "<circle cx=\"";
        append_number(out, dot.mm.x, places.position);
        out += "\" cy=\"";
        append_number(out, dot.mm.y, places.position);
        out += "\" r=\"";
        const double r = style == DotStyle::Filled ? dot.radius_mm : circle_stroke_radius(dot.radius_mm, layer.stroke_mm);
        append_number(out, std::max(r, std::pow(10.0, -places.radius)), places.radius);
        out += "\"/>\n";
    }
    out += "</g>\n";
}

void append_lines(std::string& out, const PlotLayer& layer, const std::string& ink, Places places) {
    append_layer_open(out, layer, stroke_style(ink, layer.stroke_mm));
    for (const Polyline& line : layer.lines) {
        if (line.points.empty()) continue;
        out += "<path d=\"M";
        for (size_t i = 0; i < line.points.size(); ++i) {
            if (i == 1) out += 'L';
            else if (i > 1) out += ' ';
            append_number(out, line.points[i].x, places.position);
            out += ' ';
            append_number(out, line.points[i].y, places.position);
        }
        if (line.points.size() == 1) out += "h0";  // a stroke shrunk to a point still leaves its dot
        if (line.closed) out += 'Z';
        out += "\"/>\n";
    }
    out += "</g>\n";
}

// The pen's path with the pen up: from home to each dot and to each stroke's start. A layer whose name
// starts with "%" is a documentation layer, which the AxiDraw software does not plot: the file can go
// to the plotter as it is (as a plain group the moves were plotted as lines).
void append_travel(std::string& out, const PlotPlan& plan, Places places) {
    out += "<g inkscape:groupmode=\"layer\" id=\"pen-up-travel\" inkscape:label=\"% pen-up travel (not plotted)\" fill=\"none\" "
           "stroke=\"#ff6060\" stroke-width=\"0.05\" stroke-opacity=\"0.8\">\n<path d=\"";
    glm::dvec2 pen = plan.home;
    const auto move = [&](glm::dvec2 to) {
        out += 'M';
        append_number(out, pen.x, places.position);
        out += ' ';
        append_number(out, pen.y, places.position);
        out += 'L';
        append_number(out, to.x, places.position);
        out += ' ';
        append_number(out, to.y, places.position);
        out += '\n';
    };
    for (const PlotLayer& layer : plan.layers) {
        for (const PlotDot& dot : layer.dots) {
            const std::array<glm::dvec2, 2> ends = dot_stroke_ends(dot, plan.dot_style, layer.stroke_mm);
            move(ends[0]);
            pen = ends[1];
        }
        for (const Polyline& line : layer.lines) {
            if (line.points.empty()) continue;
            move(line.points.front());
            pen = line.closed ? line.points.front() : line.points.back();
        }
    }
    out += "\"/>\n</g>\n";
}

}  // namespace

std::string svg_document(const PlotPlan& plan, bool with_travel) {
    const std::string width = format_number(plan.layout.page.width_mm, 3), height = format_number(plan.layout.page.height_mm, 3);
    std::string out;
    size_t dots = 0;
    for (const PlotLayer& layer : plan.layers) dots += layer.dots.size();
    out.reserve(1024 + 44 * dots);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" width=\"" +
           width + "mm\" height=\"" + height + "mm\" viewBox=\"0 0 " + width + " " + height + "\">\n";
    out += "<title>stipple drawing</title>\n";
    if (plan.fill_paper)
        out += "<rect width=\"" + width + "\" height=\"" + height + "\" fill=\"" + hex_colour(plan.paper) + "\" stroke=\"none\"/>\n";
    const Places places{decimals_for(plan.layout.mm_per_px, 1.0 / 10.0, 2), decimals_for(plan.layout.mm_per_px, 1.0 / 100.0, 3)};
    for (const PlotLayer& layer : plan.layers) {
        const std::string ink = hex_colour(layer.ink);
        if (layer.kind == LayerKind::Stipples) append_dots(out, layer, plan.dot_style, ink, places);
        else append_lines(out, layer, ink, places);
    }
    if (with_travel) append_travel(out, plan, places);
    out += "</svg>\n";
    return out;
}

void write_svg(const PlotPlan& plan, const std::string& path) { write_text_file(path, svg_document(plan, plan.show_travel)); }

}  // namespace stipple::plot
