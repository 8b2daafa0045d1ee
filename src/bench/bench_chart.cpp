// chart.svg: frames per second against polygon count, log-log; one series per column of ours (solid)
// and per column of the paper's Table 1 (dashed, in the colour of our matching path). Hand-written SVG.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

#include "core/printf_string.hpp"
#include "bench/bench_output.hpp"

namespace stipple::bench {

namespace {

constexpr double kWidth = 960, kHeight = 600;
constexpr double kLeft = 80, kRight = 280, kTop = 50, kBottom = 70;  // margins; the legend sits on the right
constexpr double kLegendPitch = 20;

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

const char* path_colour(DensityPath path) {
    switch (path) {
        case DensityPath::Vertex: return "#1f77b4";
        case DensityPath::Cpu: return "#d62728";
        case DensityPath::Indirect: return "#2ca02c";
        case DensityPath::Splat: return "#9467bd";
        default: return "#ff7f0e";
    }
}

// A series' marker says what it draws besides the stipples: nothing (circle), the paper's silhouettes
// (square), contours (triangle), borders (diamond) or creases (an upside-down triangle); the colour says the
// path.
enum class Marker { Circle, Square, Triangle, Diamond, DownTriangle };

Marker marker_for(const Column& c) {
    switch (c.object_lines) {
        case ObjectLines::Contours: return Marker::Triangle;
        case ObjectLines::Borders: return Marker::Diamond;
        case ObjectLines::Creases: return Marker::DownTriangle;
        case ObjectLines::None: break;
    }
    return c.lines ? Marker::Square : Marker::Circle;
}

struct Series {
    std::string label;
    std::string colour;
    bool dashed = false;
    Marker shape = Marker::Circle;
    std::vector<std::pair<double, double>> points;  // (polygons, fps), sorted by polygons
    bool with_lines() const { return shape != Marker::Circle; }
};

// A log axis from the largest 1-2-5 step at or below `lo` to the smallest at or above `hi`.
struct LogAxis {
    double lo = 1, hi = 10;
    double from = 0, to = 1;  // pixel positions of lo and hi
    LogAxis(double lo_value, double hi_value, double from_px, double to_px) : from(from_px), to(to_px) {
        lo = step_at_or_below(lo_value);
        hi = step_at_or_above(hi_value);
        if (hi <= lo) hi = step_at_or_above(lo * 1.5);
    }
    double map(double v) const { return from + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (to - from); }
    // Every k * 10^e in range (k = 1..9); `labelled` are the 1-2-5 ones.
    std::vector<std::pair<double, bool>> ticks() const {
        std::vector<std::pair<double, bool>> out;
        for (int e = int(std::floor(std::log10(lo))) - 1; e <= int(std::ceil(std::log10(hi))); ++e)
            for (int k = 1; k <= 9; ++k) {
                double v = k * std::pow(10.0, e);
                if (v >= lo * 0.999 && v <= hi * 1.001) out.emplace_back(v, k == 1 || k == 2 || k == 5);
            }
        return out;
    }
    static double step_at_or_below(double v) {
        double decade = std::pow(10.0, std::floor(std::log10(v) + 1e-9));
        for (double k : {5.0, 2.0, 1.0})
            if (k * decade <= v * (1 + 1e-9)) return k * decade;
        return decade;
    }
    static double step_at_or_above(double v) {
        double decade = std::pow(10.0, std::floor(std::log10(v) - 1e-9));
        for (double k : {1.0, 2.0, 5.0, 10.0})
            if (k * decade >= v * (1 - 1e-9)) return k * decade;
        return 10 * decade;
    }
};

std::string tick_label(double v, bool polygons) {
    if (polygons && v >= 1e6) return printf_string("%gM", v / 1e6);
    if (polygons && v >= 1e3) return printf_string("%gk", v / 1e3);
    return printf_string("%g", v);
}

std::vector<Series> collect_series(const BenchResults& r) {
    std::vector<Series> series;
    for (const Column& c : r.columns) {
        Series s{"ours: " + c.name(), path_colour(c.path), false, marker_for(c), {}};
        for (const ModelResult& m : r.models)
            for (const CellResult& cell : m.cells)
                if (cell.column == c && cell.median_fps > 0)
                    s.points.emplace_back(double(m.entry.triangles), cell.median_fps);
        std::sort(s.points.begin(), s.points.end());
        if (!s.points.empty()) series.push_back(std::move(s));
    }
    // The paper's columns, over the rows this run measured (all rows when it measured none).
    for (DensityPath path : {DensityPath::Vertex, DensityPath::Cpu})
        for (bool lines : {false, true}) {
            Column c{path, lines};
            std::string label = std::string("paper: ") + (path == DensityPath::Vertex ? "vertex program" : "no vertex program");
            Series s{label + (lines ? " + lines" : ""), path_colour(path), true, lines ? Marker::Square : Marker::Circle, {}};
            for (const PaperRow& row : kPaperTable) {
                bool measured = r.models.empty();
                for (const ModelResult& m : r.models) measured |= m.entry.name == row.name;
                if (measured) s.points.emplace_back(double(row.polygons), *paper_fps(row, c));
            }
            if (!s.points.empty()) series.push_back(std::move(s));
        }
    return series;
}

void marker(std::ostringstream& svg, const Series& s, double x, double y) {
    // Hollow for the paper, filled for ours.
    const std::string paint = s.dashed ? "fill=\"white\" stroke=\"" + s.colour + "\"" : "fill=\"" + s.colour + "\"";
    auto polygon = [&](std::initializer_list<std::pair<double, double>> corners) {
        std::string points;
        for (auto [dx, dy] : corners) points += printf_string("%.1f,%.1f ", x + dx, y + dy);
        svg << printf_string("<polygon points=\"%s\" %s/>\n", points.c_str(), paint.c_str());
    };
    switch (s.shape) {
        case Marker::Circle:
            svg << printf_string("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3.5\" %s/>\n", x, y, paint.c_str());
            break;
        case Marker::Square:
            svg << printf_string("<rect x=\"%.1f\" y=\"%.1f\" width=\"7\" height=\"7\" %s/>\n", x - 3.5, y - 3.5, paint.c_str());
            break;
        case Marker::Triangle: polygon({{0, -4.5}, {4.5, 3.5}, {-4.5, 3.5}}); break;
        case Marker::Diamond: polygon({{0, -4.5}, {4.5, 0}, {0, 4.5}, {-4.5, 0}}); break;
        case Marker::DownTriangle: polygon({{0, 4.5}, {4.5, -3.5}, {-4.5, -3.5}}); break;
    }
}

}  // namespace

std::string svg_chart(const BenchResults& r) {
    std::vector<Series> series = collect_series(r);
    double x_lo = 1e4, x_hi = 1e6, y_lo = 1.0, y_hi = 100.0;
    bool first = true;
    for (const Series& s : series)
        for (auto [x, y] : s.points) {
            if (first) x_lo = x_hi = x, y_lo = y_hi = y, first = false;
            x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x), y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
        }
    // Taller than the default where the legend needs it (a run of every path has 29 series).
    const double height = std::max(kHeight, kTop + 8 + kLegendPitch * double(series.size()) + 10);
    const double plot_right = kWidth - kRight, plot_bottom = height - kBottom;
    LogAxis xa(x_lo, x_hi, kLeft, plot_right), ya(y_lo, y_hi, plot_bottom, kTop);

    std::ostringstream svg;
    svg << printf_string("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
                  "font-family=\"Helvetica, Arial, sans-serif\" font-size=\"12\">\n",
                  kWidth, height, kWidth, height);
    svg << printf_string("<rect width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n", kWidth, height);
    svg << printf_string("<text x=\"%.0f\" y=\"24\" font-size=\"15\" font-weight=\"bold\">%s</text>\n", kLeft,
                  escape(printf_string("Frames per second against polygon count, %ux%u", r.width, r.height)).c_str());
    svg << printf_string("<text x=\"%.0f\" y=\"40\" fill=\"#555\">%s</text>\n", kLeft,
                  escape("ours: " + r.device + " (solid); paper: GeForce3 Ti 500, 2002 (dashed)").c_str());

    // Grid, ticks and tick labels: 1-2-5 steps labelled, the rest as minor ticks; decades darker.
    for (auto [v, labelled] : xa.ticks()) {
        double x = xa.map(v);
        bool decade = std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9;
        svg << printf_string("<line x1=\"%.1f\" y1=\"%.0f\" x2=\"%.1f\" y2=\"%.0f\" stroke=\"%s\"/>\n", x, kTop, x, plot_bottom,
                      decade ? "#bbb" : "#eee");
        svg << printf_string("<line x1=\"%.1f\" y1=\"%.0f\" x2=\"%.1f\" y2=\"%.0f\" stroke=\"black\"/>\n", x, plot_bottom, x,
                      plot_bottom + (labelled ? 6 : 3));
        if (labelled)
            svg << printf_string("<text x=\"%.1f\" y=\"%.0f\" text-anchor=\"middle\">%s</text>\n", x, plot_bottom + 20,
                          tick_label(v, true).c_str());
    }
    for (auto [v, labelled] : ya.ticks()) {
        double y = ya.map(v);
        bool decade = std::abs(std::log10(v) - std::round(std::log10(v))) < 1e-9;
        svg << printf_string("<line x1=\"%.0f\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"%s\"/>\n", kLeft, y, plot_right, y,
                      decade ? "#bbb" : "#eee");
        svg << printf_string("<line x1=\"%.0f\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"black\"/>\n",
                      kLeft - (labelled ? 6 : 3), y, kLeft, y);
        if (labelled)
            svg << printf_string("<text x=\"%.0f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", kLeft - 9, y + 4,
                          tick_label(v, false).c_str());
    }
    svg << printf_string("<rect x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" height=\"%.0f\" fill=\"none\" stroke=\"black\"/>\n",
                  kLeft, kTop, plot_right - kLeft, plot_bottom - kTop);
    svg << printf_string("<text x=\"%.0f\" y=\"%.0f\" text-anchor=\"middle\">polygons (triangles), log scale</text>\n",
                  (kLeft + plot_right) / 2, height - 25);
    svg << printf_string("<text transform=\"translate(24 %.0f) rotate(-90)\" text-anchor=\"middle\">frames per second, "
                  "log scale</text>\n",
                  (kTop + plot_bottom) / 2);

    // The series.
    for (const Series& s : series) {
        std::string points;
        for (auto [x, y] : s.points) points += printf_string("%.1f,%.1f ", xa.map(x), ya.map(y));
        svg << printf_string("<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"%s\"%s/>\n", points.c_str(),
                      s.colour.c_str(), s.with_lines() ? "1.5" : "2", s.dashed ? " stroke-dasharray=\"6 4\"" : "");
        for (auto [x, y] : s.points) marker(svg, s, xa.map(x), ya.map(y));
    }

    // The legend.
    double lx = plot_right + 20, ly = kTop + 8;
    for (const Series& s : series) {
        svg << printf_string("<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"%s\" stroke-width=\"2\"%s/>\n",
                      lx, ly, lx + 28, ly, s.colour.c_str(), s.dashed ? " stroke-dasharray=\"6 4\"" : "");
        marker(svg, s, lx + 14, ly);
        svg << printf_string("<text x=\"%.0f\" y=\"%.0f\" font-size=\"11\">%s</text>\n", lx + 36, ly + 4,
                      escape(s.label).c_str());
        ly += kLegendPitch;
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace stipple::bench
