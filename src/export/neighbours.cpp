#include "export/neighbours.hpp"

#include <algorithm>
#include <cmath>

#include <nanoflann.hpp>

#include "core/parallel.hpp"

namespace stipple::plot {

namespace {

// nanoflann's view of the points (it reads them in place).
struct PointCloud {
    std::span<const glm::dvec2> points;
    size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(size_t index, size_t dim) const { return points[index][static_cast<int>(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2, uint32_t>;

}  // namespace

NeighbourLists nearest_neighbours(std::span<const glm::dvec2> points, uint32_t k) {
    NeighbourLists lists;
    k = std::min<uint32_t>(k, 255);  // counts are bytes
    lists.k = k;
    lists.indices.assign(points.size() * k, 0);
    lists.count.assign(points.size(), 0);
    if (points.size() < 2 || k == 0) return lists;

    const PointCloud cloud{points};
    const KdTree tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    // Each chunk writes only its own rows, so the lists do not depend on the thread count.
    parallel_for_chunks(points.size(), 4096, [&](size_t, size_t begin, size_t end) {
        std::vector<uint32_t> found(k + 1);
        std::vector<double> dist_sq(k + 1);
        for (size_t i = begin; i < end; ++i) {
            const double query[2] = {points[i].x, points[i].y};
            const size_t n = tree.knnSearch(query, k + 1, found.data(), dist_sq.data());
            uint8_t written = 0;
            for (size_t j = 0; j < n && written < k; ++j)
                if (found[j] != i) lists.indices[i * k + written++] = found[j];
            lists.count[i] = written;
        }
    });
    return lists;
}

double nearest_neighbour_bound(std::span<const glm::dvec2> points) {
    const NeighbourLists nearest = nearest_neighbours(points, 1);
    double sum = 0.0;
    for (size_t i = 0; i < points.size(); ++i)
        if (nearest.count[i] > 0) {
            const glm::dvec2 d = points[nearest.indices[i]] - points[i];
            sum += std::sqrt(d.x * d.x + d.y * d.y);
        }
    return sum;
}

}  // namespace stipple::plot
