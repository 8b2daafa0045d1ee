// The plot-order row as Markdown (the JSON is written with the rest in bench_json.cpp).
#include "core/printf_string.hpp"
#include "bench/plot_order_row.hpp"

#include <cstdio>

#include "bench/bench_output.hpp"

namespace stipple::bench {

std::string plot_order_markdown(const PlotOrderRow& row) {
    std::string md = "## Plot order (pen plotters)\n\n";
    md += "Dots ordered for a plotter (nearest-neighbour tour, 2-opt, Or-opt): the time to order them and the "
          "pen-up travel between dots against its lower bound (the sum of each dot's distance to its nearest "
          "neighbour; a random order is tens of times over it). The bunny's figure is the whole plot plan "
          "(order, lines, page) of the visible stipples of its default view, as `stipple render -o x.svg` "
          "makes it.\n\n";
    md += "| dot set | dots | ordering s | travel / lower bound | random order / lower bound |\n";
    md += "|---|---:|---:|---:|---:|\n";
    if (row.blue_noise) {
        const PlotOrderFigures& f = *row.blue_noise;
        md += printf_string("| blue noise, A4 | %s | %.3f | %.3f | %.1f |\n", with_commas(f.dots).c_str(), f.order_seconds,
                     f.travel_ratio, f.random_ratio);
    }
    if (row.bunny_view) {
        const PlotOrderFigures& f = *row.bunny_view;
        md += printf_string("| bunny, default view (captured in %.2f s) | %s | %.3f | %.3f | – |\n", f.capture_seconds,
                     with_commas(f.dots).c_str(), f.order_seconds, f.travel_ratio);
    } else {
        md += "| bunny, default view | – | – | – | – |\n";
    }
    md += "\n";
    if (!row.bunny_view && !row.bunny_note.empty()) md += "The bunny: " + row.bunny_note + "\n\n";
    return md;
}

}  // namespace stipple::bench
