// Speed and quality of the plotter order on blue-noise dot sets (the projection of a stippled
// surface): times the k-d tree's neighbour lists, the nearest-neighbour tour and the 2-opt/Or-opt
// improvement, and prints each path's pen-up travel against its lower bound (the sum of the
// nearest-neighbour distances). With --compare it also times the nearest-neighbour tour done with
// nanoflann's dynamic index (removing visited dots) instead of the grid, which is why the grid is used.
// With --out DIR it also builds a whole plot of a stippled, outlined sphere (plan, SVG, PDF, CSV,
// timed) and writes it there, with sphere-travel.svg showing the pen-up moves.
// Prints figures only; the test suite asserts the quality, never the time.
// Usage: plot_order_speed [--compare] [--out DIR] [COUNT ...]   (default: 150000)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <numbers>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
// nanoflann's dynamic index (used here only for the comparison) trips GCC 12's
// maybe-uninitialized analysis inside the library's own header (clang has no such warning).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <nanoflann.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "core/error.hpp"
#include "export/blue_noise.hpp"
#include "export/csv_writer.hpp"
#include "export/pdf_writer.hpp"
#include "export/plot_plan.hpp"
#include "export/plot_stats.hpp"
#include "export/svg_writer.hpp"
#include "export/text_format.hpp"
#include "export/dot_order.hpp"
#include "export/neighbours.hpp"
#include "export/order_speed.hpp"
#include "export/tour_improve.hpp"

namespace {

using namespace stipple::plot;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Cloud {
    std::span<const glm::dvec2> points;
    size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(size_t index, size_t dim) const { return points[index][static_cast<int>(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};

// The same tour with nanoflann's dynamic index: visited dots are removed from it and skipped by
// its searches, but still walked through.
std::vector<uint32_t> nanoflann_tour(std::span<const glm::dvec2> points, glm::dvec2 pen) {
    using Index = nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 2, uint32_t>;
    const Cloud cloud{points};
    Index index(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    std::vector<uint32_t> order;
    glm::dvec2 at = pen;
    for (size_t step = 0; step < points.size(); ++step) {
        uint32_t found = 0;
        double dist_sq = 0.0;
        nanoflann::KNNResultSet<double, uint32_t> result(1);
        result.init(&found, &dist_sq);
        const double query[2] = {at.x, at.y};
        index.findNeighbors(result, query, nanoflann::SearchParams());
        order.push_back(found);
        index.removePoint(found);
        at = points[found];
    }
    return order;
}

void measure(size_t count, bool compare) {
    const OrderSpeed s = measure_order_speed(count);
    const std::span<const glm::dvec2> points = s.points;
    const glm::dvec2 pen(0.0);
    const double bound = s.bound_mm;
    std::printf("%zu dots (blue noise, %.3f mm apart, generated in %.2f s)\n", points.size(), s.spacing_mm, s.generate_s);
    std::printf("  neighbour lists (k-d tree, k=8): %.3f s\n", s.lists_s);
    std::printf("  nearest-neighbour tour (grid):   %.3f s, travel %.0f mm = %.3f x bound\n", s.tour_s, s.tour_mm, s.tour_mm / bound);
    std::printf("  2-opt + Or-opt:                  %.3f s (%zu + %zu moves), travel %.0f mm = %.3f x bound\n", s.improve_s,
                s.moves.two_opt_moves, s.moves.or_opt_moves, s.improved_mm, s.improved_mm / bound);
    std::printf("  plot_order, all steps:           %.3f s, travel %.0f mm = %.3f x bound\n", s.plot_order_s, s.plot_order_mm,
                s.ratio());
    std::printf("  lower bound %.0f mm; random order %.0f mm = %.1f x bound\n", bound, s.random_mm, s.random_mm / bound);
    if (compare) {
        const auto start = Clock::now();
        const std::vector<uint32_t> kd_order = nanoflann_tour(points, pen);
        const double kd_s = seconds_since(start);
        std::printf("  nearest-neighbour tour (nanoflann dynamic index): %.3f s, travel %.0f mm = %.3f x bound\n", kd_s,
                    travel_length(points, kd_order, pen), travel_length(points, kd_order, pen) / bound);
    }
}

// A lit sphere as the renderer would hand it over: blue-noise stipples kept with probability
// 1 - N.L (darker away from the light, the fractional last ones lighter), and its outline as
// 720 pieces, each third one reported twice and the whole given in shuffled order.
Drawing sphere_drawing(size_t candidates) {
    Drawing drawing;
    drawing.width_px = 1280;
    drawing.height_px = 1024;
    drawing.objects.push_back({"sphere", 2.0f});
    const glm::dvec2 centre(640.0, 512.0);
    const double radius = 450.0;
    const glm::dvec3 light = glm::normalize(glm::dvec3(-0.5, -0.6, 0.62));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double side = 2.0 * radius;
    for (const glm::dvec2& p : poisson_disc_points(side, side, poisson_disc_spacing(side, side, candidates), 2)) {
        const glm::dvec2 q = (p - glm::dvec2(radius)) / radius;
        const double r2 = glm::dot(q, q);
        if (r2 >= 1.0) continue;
        const glm::dvec3 normal(q.x, q.y, std::sqrt(1.0 - r2));
        const double darkness = 1.0 - std::max(0.0, glm::dot(normal, light));
        const double u = unit(rng);
        if (u > darkness) continue;
        const float intensity = u > darkness - 0.05 ? 0.4f : 1.0f;
        drawing.dots.push_back({glm::vec2(centre + p - glm::dvec2(radius)), 1.0f, intensity, 0, static_cast<uint32_t>(drawing.dots.size() / 4)});
    }
    std::vector<Segment> outline;
    for (int i = 0; i < 720; ++i) {
        const double a0 = 2.0 * std::numbers::pi * i / 720, a1 = 2.0 * std::numbers::pi * (i + 1) / 720;
        const glm::vec2 p0(centre + radius * glm::dvec2(std::cos(a0), std::sin(a0))), p1(centre + radius * glm::dvec2(std::cos(a1), std::sin(a1)));
        outline.push_back({p0, p1, 0, LineKind::Silhouette});
        if (i % 3 == 0) outline.push_back({p1, p0, 0, LineKind::Silhouette});
    }
    std::shuffle(outline.begin(), outline.end(), rng);
    drawing.segments = outline;
    return drawing;
}

void whole_plot(size_t candidates, const std::string& dir) {
    const Drawing drawing = sphere_drawing(candidates);
    ExportOptions options;
    options.page = parse_page("A4-landscape");
    options.pen_width_mm = 0.3;
    auto start = Clock::now();
    const PlotPlan plan = make_plot_plan(drawing, options);
    const double plan_s = seconds_since(start);
    start = Clock::now();
    const std::string svg = svg_document(plan);
    write_text_file(dir + "/sphere.svg", svg);
    const double svg_s = seconds_since(start);
    start = Clock::now();
    write_pdf(plan, dir + "/sphere.pdf");
    const double pdf_s = seconds_since(start);
    start = Clock::now();
    write_csv(plan, dir + "/sphere.csv");
    const double csv_s = seconds_since(start);
    write_text_file(dir + "/sphere-travel.svg", svg_document(plan, true));
    std::printf("sphere plot: %zu dots, %zu outline pieces; plan (order, lines) %.3f s, SVG %.3f s (%.1f bytes a dot), PDF %.3f s, CSV %.3f s\n",
                drawing.dots.size(), drawing.segments.size(), plan_s, svg_s, double(svg.size()) / double(drawing.dots.size()), pdf_s, csv_s);
    std::printf("  %s\n", format_stats(plot_stats(plan)).c_str());
}

}  // namespace

int main(int argc, char** argv) {
    bool compare = false;
    std::string out_dir;
    std::vector<size_t> counts;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
            std::printf("usage: plot_order_speed [--compare] [--out DIR] [COUNT ...]   (default: 150000)\n"
                        "  times the plotter order on COUNT blue-noise dots and prints its travel against the lower\n"
                        "  bound; --compare also times nanoflann's dynamic index; --out DIR writes a whole plot there\n");
            return 0;
        }
        if (std::strcmp(argv[i], "--compare") == 0) compare = true;
        else if (std::strcmp(argv[i], "--out") == 0 && i + 1 < argc) out_dir = argv[++i];
        else if (const unsigned long long n = std::strtoull(argv[i], nullptr, 10); n > 0) counts.push_back(n);
        else {
            std::fprintf(stderr, "plot_order_speed: '%s' is not a dot count (usage: plot_order_speed [--compare] [--out DIR] [COUNT ...])\n", argv[i]);
            return 1;
        }
    }
    if (counts.empty()) counts = {150000};
    try {
        for (const size_t count : counts) measure(count, compare);
        if (!out_dir.empty()) {
            std::error_code ec;  // a missing folder is made, as render's -o makes one
            std::filesystem::create_directories(out_dir, ec);
            if (ec) stipple::fail_file(out_dir, "cannot make the folder: " + ec.message());
            whole_plot(counts.front(), out_dir);
        }
    } catch (const stipple::Error& e) {
        std::fprintf(stderr, "plot_order_speed: %s\n", e.what());
        return 1;
    }
    return 0;
}
