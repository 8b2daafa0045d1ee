// Speed and quality of the plotter order on blue-noise dot sets (the projection of a stippled
// surface): times the k-d tree's neighbour lists, the nearest-neighbour tour and the 2-opt/Or-opt
// improvement, and prints each path's pen-up travel against its lower bound (the sum of the
// nearest-neighbour distances). With --compare it also times the nearest-neighbour tour done with
// nanoflann's dynamic index (removing visited dots) instead of the grid, which is why the grid is used.
// Prints figures only; the test suite asserts the quality, never the time.
// Usage: plot_order_speed [--compare] [COUNT ...]   (default: 150000)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <random>
#include <span>
#include <vector>

#include <nanoflann.hpp>

#include "export/blue_noise.hpp"
#include "export/dot_order.hpp"
#include "export/neighbours.hpp"
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
    // An A4-sized field (mm), as a page of stipples would be.
    const double width = 190.0, height = 277.0;
    auto start = Clock::now();
    const std::vector<glm::dvec2> points = poisson_disc_points(width, height, poisson_disc_spacing(width, height, count), 1);
    const double generate_s = seconds_since(start);
    const glm::dvec2 pen(0.0);

    start = Clock::now();
    const NeighbourLists lists = nearest_neighbours(points, 8);
    const double lists_s = seconds_since(start);
    start = Clock::now();
    std::vector<uint32_t> order = nearest_neighbour_tour(points, lists, pen);
    const double tour_s = seconds_since(start);
    const double tour_travel = travel_length(points, order, pen);
    start = Clock::now();
    const ImproveCounts moves = improve_path(points, lists, order);
    const double improve_s = seconds_since(start);
    const double improved_travel = travel_length(points, order, pen);

    start = Clock::now();
    const std::vector<uint32_t> full = plot_order(points, pen);
    const double plot_order_s = seconds_since(start);
    const double bound = nearest_neighbour_bound(points);

    std::vector<uint32_t> shuffled(points.size());
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
    const double random_travel = travel_length(points, shuffled, pen);

    std::printf("%zu dots (blue noise, %.3f mm apart, generated in %.2f s)\n", points.size(),
                poisson_disc_spacing(width, height, count), generate_s);
    std::printf("  neighbour lists (k-d tree, k=8): %.3f s\n", lists_s);
    std::printf("  nearest-neighbour tour (grid):   %.3f s, travel %.0f mm = %.3f x bound\n", tour_s, tour_travel, tour_travel / bound);
    std::printf("  2-opt + Or-opt:                  %.3f s (%zu + %zu moves), travel %.0f mm = %.3f x bound\n", improve_s,
                moves.two_opt_moves, moves.or_opt_moves, improved_travel, improved_travel / bound);
    std::printf("  plot_order, all steps:           %.3f s, travel %.0f mm = %.3f x bound\n", plot_order_s,
                travel_length(points, full, pen), travel_length(points, full, pen) / bound);
    std::printf("  lower bound %.0f mm; random order %.0f mm = %.1f x bound\n", bound, random_travel, random_travel / bound);
    if (compare) {
        start = Clock::now();
        const std::vector<uint32_t> kd_order = nanoflann_tour(points, pen);
        const double kd_s = seconds_since(start);
        std::printf("  nearest-neighbour tour (nanoflann dynamic index): %.3f s, travel %.0f mm = %.3f x bound\n", kd_s,
                    travel_length(points, kd_order, pen), travel_length(points, kd_order, pen) / bound);
    }
}

}  // namespace

int main(int argc, char** argv) {
    bool compare = false;
    std::vector<size_t> counts;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--compare") == 0) compare = true;
        else if (const unsigned long long n = std::strtoull(argv[i], nullptr, 10); n > 0) counts.push_back(n);
        else {
            std::fprintf(stderr, "plot_order_speed: '%s' is not a dot count (usage: plot_order_speed [--compare] [COUNT ...])\n", argv[i]);
            return 1;
        }
    }
    if (counts.empty()) counts = {150000};
    for (const size_t count : counts) measure(count, compare);
    return 0;
}
