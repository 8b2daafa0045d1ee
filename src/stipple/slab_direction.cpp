#include "stipple/slab_direction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"

namespace stipple {

double SlabRule::wanted_width(double object_size) const {
    return std::max(object_size / slabs, min_slab_searches * search_cap * spacing);
}

float SlabRule::split_extent(double object_size) const {
    return static_cast<float>(0.5 * (wanted_width(object_size) - search_cap * spacing));
}

double SlabRule::slab_count(double object_size) const { return std::ceil(object_size / wanted_width(object_size)); }

namespace {

uint64_t stipples_cut(const SlabDirection& choice, std::span<const uint32_t> first, const SlabRule& rule) {
    const float split = rule.split_extent(choice.size);
    uint64_t cut = 0;
    for (size_t t = 0; t + 1 < first.size(); ++t)
        if (choice.extent[t] > split) cut += first[t + 1] - first[t];
    return cut;
}

// The stipples' span along unit direction d, and each triangle's centroid along it and reach from that.
SlabDirection measure_along(glm::vec3 d, std::span<const glm::vec3> positions, std::span<const uint32_t> first,
                            std::span<const glm::vec3> centre) {
    SlabDirection along;
    along.direction = d;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const glm::vec3& p : positions) lo = std::min(lo, glm::dot(p, d)), hi = std::max(hi, glm::dot(p, d));
    along.lo = lo;
    along.size = double(hi) - double(lo);
    along.centre.assign(centre.size(), 0.0f);
    along.extent.assign(centre.size(), 0.0f);
    parallel_for_chunks(centre.size(), 4096, [&](size_t, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            along.centre[t] = glm::dot(centre[t], d);
            for (uint32_t i = first[t]; i < first[t + 1]; ++i)
                along.extent[t] = std::max(along.extent[t], std::abs(glm::dot(positions[i] - centre[t], d)));
        }
    });
    return along;
}

// The direction the cut triangles share: the principal eigenvector of the sum, weighted by their counts, of
// r r^T over the unit vectors r from their centroids to their farthest stipples (power iteration). Zero
// when there is none.
glm::vec3 cut_triangles_direction(const SlabDirection& choice, std::span<const glm::vec3> positions,
                                  std::span<const uint32_t> first, std::span<const glm::vec3> centre,
                                  const SlabRule& rule) {
    const float split = rule.split_extent(choice.size);
    glm::mat3 spread(0.0f);
    for (size_t t = 0; t + 1 < first.size(); ++t) {
        if (!(choice.extent[t] > split)) continue;
        glm::vec3 reach(0.0f);
        for (uint32_t i = first[t]; i < first[t + 1]; ++i) {
            const glm::vec3 d = positions[i] - centre[t];
            if (glm::dot(d, d) > glm::dot(reach, reach)) reach = d;
        }
        if (glm::dot(reach, reach) > 0.0f) {
            const glm::vec3 r = glm::normalize(reach);
            spread += float(first[t + 1] - first[t]) * glm::outerProduct(r, r);
        }
    }
    glm::vec3 along = spread[0] + spread[1] + spread[2] + glm::vec3(1e-3f, 2e-3f, 3e-3f);  // not across it
    for (int i = 0; i < 32; ++i) {
        const float norm = glm::length(along);
        if (!(norm > 0.0f) || !std::isfinite(norm)) return glm::vec3(0.0f);
        along = spread * (along / norm);
    }
    const float norm = glm::length(along);
    return norm > 0.0f && std::isfinite(norm) ? along / norm : glm::vec3(0.0f);
}

}  // namespace

SlabDirection choose_slab_direction(std::span<const glm::vec3> positions, std::span<const uint32_t> first,
                                    const SlabRule& rule) {
    const size_t triangles = first.size() - 1;
    glm::vec3 lo = positions[0], hi = positions[0];
    for (const glm::vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 size = hi - lo;
    const int longest = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);

    // Centroid and extent on each axis (the farthest stipple from the centroid) of each triangle's stipples.
    std::vector<glm::vec3> centre(triangles, glm::vec3(0.0f)), extent(triangles, glm::vec3(0.0f));
    parallel_for_chunks(triangles, 4096, [&](size_t, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const uint32_t b = first[t], e = first[t + 1];
            if (b == e) continue;
            glm::vec3 sum(0.0f);
            for (uint32_t i = b; i < e; ++i) sum += positions[i];
            const glm::vec3 m = sum / float(e - b);
            for (uint32_t i = b; i < e; ++i) extent[t] = glm::max(extent[t], glm::abs(positions[i] - m));
            centre[t] = m;
        }
    });
    // An axis across which the object is too thin for two slabs (a plane seen edge-on: nothing cut, one
    // slab, one core) is not taken while the longest gives two.
    const double fewest_slabs = std::min(2.0, rule.slab_count(size[longest]));
    SlabDirection choice;
    choice.cut_stipples = std::numeric_limits<uint64_t>::max();
    for (int a : {longest, (longest + 1) % 3, (longest + 2) % 3}) {
        if (rule.slab_count(size[a]) < fewest_slabs) continue;
        SlabDirection axis;
        axis.direction[0] = 0.0f;
        axis.direction[a] = 1.0f;
        axis.lo = lo[a];
        axis.size = size[a];
        axis.centre.resize(triangles);
        axis.extent.resize(triangles);
        for (size_t t = 0; t < triangles; ++t) axis.centre[t] = centre[t][a], axis.extent[t] = extent[t][a];
        axis.cut_stipples = stipples_cut(axis, first, rule);
        if (axis.cut_stipples < choice.cut_stipples) choice = std::move(axis);
    }
    // Slivers along no axis (a CAD part's tilted pipe) are cut by every axis: directions across the cut
    // triangles' common direction are tried as the axes were, and one taken only where it cuts at most half
    // as many (a cylinder's fanned caps are cut about the same across any direction of their plane, and
    // an axis makes the same stipples as before). With one slab a cut triangle is one piece anyway.
    if (choice.cut_stipples == 0 || fewest_slabs < 2.0) return choice;
    const glm::vec3 along = cut_triangles_direction(choice, positions, first, centre, rule);
    if (along == glm::vec3(0.0f)) return choice;
    const glm::vec3 a = glm::abs(along);
    const glm::vec3 least = a.x <= a.y && a.x <= a.z ? glm::vec3(1, 0, 0) : (a.y <= a.z ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
    const glm::vec3 u0 = glm::normalize(glm::cross(along, least)), u1 = glm::cross(along, u0);
    for (int k = 0; k < 4; ++k) {
        const double angle = 0.7853981633974483 * k;  // k * 45 degrees
        SlabDirection across =
            measure_along(float(std::cos(angle)) * u0 + float(std::sin(angle)) * u1, positions, first, centre);
        if (rule.slab_count(across.size) < fewest_slabs) continue;
        across.cut_stipples = stipples_cut(across, first, rule);
        if (2 * across.cut_stipples <= choice.cut_stipples) choice = std::move(across);
    }
    return choice;
}

}  // namespace stipple
