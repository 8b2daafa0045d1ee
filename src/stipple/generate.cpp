// Stipple generation: the candidate stipples of one object (Lu et al. 2002, §2.1 "Initial Point
// Generation").
//
// The paper generates random points in every polygon, redistributes them toward a Poisson-disc
// distribution, and gives polygon i  N_max = Object_max * min(D_max, D_r)  stipples, where D_r
// follows "the initial screen area of the projected polygon" so that "the stipple pattern is
// independent of the object tessellation". Our reading, precisely:
//
// * Reference scale. The object is framed so that its bounding-sphere radius R spans
//   kReferenceHeight / 2 pixels: px_per_unit = (kReferenceHeight / 2) / R, and triangle i has the
//   reference area a_i = area_i * px_per_unit^2. The polygon is taken as facing the camera: the
//   paper's orientation and depth terms (cos(N_z * pi), Z_rel) change every frame and belong to
//   the per-frame density pass, not to generation.
// * Density, in stipples per reference pixel^2: d = min(D_max, Object_max / sum_i a_i). D_r is
//   read as the density the object's budget affords, so the budget lowers the density evenly over
//   the surface instead of truncating some triangles. stipple_density_per_area = d * px_per_unit^2
//   (stipples per object-space unit area).
// * Counts. Triangle i expects E_i = density_per_area * area_i stipples. The integer count comes
//   from cumulative rounding in triangle order, N_i = floor(S_i + 0.5) - floor(S_{i-1} + 0.5) with
//   S_i = E_1 + ... + E_i: every N_i is within 1 of E_i, and the total is within 1 of the exact
//   total density * area however finely the surface is tessellated (rounding each triangle on its
//   own would lose or gain up to half a stipple per triangle, which dominates on dense meshes).
//   Zero-area triangles expect 0 and get 0. An animated model's triangles expect E_i * h_i, h_i
//   their stretch headroom (src/anim/headroom.hpp), so that a stretched triangle finds candidates
//   for its larger area; the per-frame density asks for E_i * (current area / rest area) of them.
// * Positions. Stratified in the triangle: point k of triangle t is the k-th point of the R2
//   low-discrepancy sequence (Roberts 2018: k * (1/g, 1/g^2) mod 1, g the plastic number) shifted by
//   a random offset keyed by (seed, triangle), folded from the unit square onto the triangle
//   ((u, v) -> (1 - u, 1 - v) when u + v > 1, which keeps it uniform). Deterministic, and
//   independent of the thread count and of the order in which triangles are processed. Starting
//   the relaxation from stratified rather than independent points leaves fewer clumps for it to
//   undo: delta-bar after 6 iterations (then the default) rose from 0.832 to 0.838 on a 100k-triangle
//   sphere with 4 stipples per triangle, and from 0.828 to 0.868 on a 12-triangle cube (Jacobi
//   relaxation, before 2026-11-26). But R2 is a lattice of one orientation, and a large triangle's
//   relaxed stipples kept it: hexagonal domains aligned over the whole triangle (six-fold order
//   |<psi_6>| 0.32-0.40 over windows of an eighth of a 40k-stipple square, against 0.05 for dart
//   throwing; quality.hpp). Each point is therefore jittered by up to a quarter of the sequence's
//   spacing either way (kJitter = 0.5 of 1/sqrt(N) in all): the order falls to 0.07 while
//   delta-bar keeps its gain (square 0.874, cube 0.870, sphere 0.858 after Gauss-Seidel relaxation).
// * Relaxation (relax.cpp). A few Gauss-Seidel iterations of repulsion between neighbours within two
//   hexagonal spacings, over the whole surface (not per triangle, which would leave stipples
//   clumped along shared edges of small triangles); moves stay in the triangle's plane and each
//   stipple is clamped back into its own triangle.
// * Progressive order (progressive_order.cpp). Within each triangle the stipples are stored so
//   that the first ones, kept at low density, are well spread over the whole surface.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "stipple/progressive_order.hpp"
#include "stipple/relax.hpp"
#include "stipple/stipple_classes.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

namespace {

constexpr size_t kTriangleChunk = 16384;
constexpr size_t kPointChunk = 16384;
// Jitter of the stratified positions, in units of the R2 sequence's spacing in its unit square (1/sqrt(N)):
// breaks its lattice orientation (see the top of this file).
constexpr double kJitter = 0.5;
// The coarse class's own iterations (stipple_classes.hpp): as many as the whole set's (relax_stipples adds
// kFreeIterations to them with the class). With the default 5 + 2, the quarter's delta-bar after 5 and 7
// of its own: 0.799 and 0.809 on the 100k-triangle sphere of 400k stipples (tests/test_generation.cpp).
// Started from the triangles' centroids instead of the sequence's hashed offsets it reached 0.812 in 5, but the many copies of a part then placed their first stipples
// alike, and the polygon selection, which ranks the triangles by them, came to follow the faces' facing
// below what its calibration detects (SelectionValues.UniformForEveryFacingOfRepeatedParts: up to 4
// standard errors, 0.528 of a facing's faces below p = 0.5).
int coarse_iterations(int relax_iterations) { return relax_iterations + kFreeIterations; }

// The name errors start with: the file the mesh came from, or its generator's name.
std::string source_name(const Mesh& mesh) { return mesh.source.empty() ? std::string("mesh") : mesh.source; }

void check_params(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom = {}) {
    const std::string name = source_name(mesh);
    if (!std::isfinite(params.dmax) || params.dmax < 0.0f)
        fail_file(name, "stipple density D_max must be a finite number >= 0, got " + std::to_string(params.dmax));
    if (params.relax_iterations < 0 || params.relax_iterations > 1000)
        fail_file(name, "relaxation iterations must be in [0, 1000], got " + std::to_string(params.relax_iterations));
    if (mesh.indices.size() % 3 != 0)
        fail_file(name, "index count " + std::to_string(mesh.indices.size()) + " is not a multiple of 3");
    STIPPLE_CHECK(headroom.empty() || headroom.size() == mesh.triangle_count(), "one headroom factor per triangle");
    for (float h : headroom) STIPPLE_CHECK(std::isfinite(h) && h >= 1.0f, "headroom factors are finite and >= 1");
}

// Triangles whose areas are computed at a time (see for_each_area_block): 1 MiB of doubles, reused.
constexpr size_t kAreaBlock = size_t(1) << 17;

// Calls visit(first_triangle, areas) for consecutive blocks of triangles, in order, with the area of
// each in double, computed on every core. Generation reads the areas twice (their sum, then the counts);
// storing them took 8 bytes a triangle of memory touched for the first time, which on a virtual machine
// costs more than computing them again (a 4M-triangle mesh: 72 ms for its 32 MiB of areas, 14 ms of
// which computing them). Throws on an index out of range or a non-finite area.
template <class Visit>
void for_each_area_block(const Mesh& mesh, Visit&& visit) {
    const size_t triangles = mesh.triangle_count();
    const size_t vertex_count = mesh.positions.size();
    std::vector<double> area(std::min(triangles, kAreaBlock));
    for (size_t first = 0; first < triangles; first += kAreaBlock) {
        const size_t count = std::min(kAreaBlock, triangles - first);
        parallel_for_chunks(count, kTriangleChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t t = first + begin; t < first + end; ++t) {
                const uint32_t ia = mesh.indices[3 * t], ib = mesh.indices[3 * t + 1], ic = mesh.indices[3 * t + 2];
                if (ia >= vertex_count || ib >= vertex_count || ic >= vertex_count)
                    fail_file(source_name(mesh), "face " + std::to_string(t) + " refers to a vertex out of range");
                const glm::dvec3 a(mesh.positions[ia]);
                const double value =
                    0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[ib]) - a, glm::dvec3(mesh.positions[ic]) - a));
                if (!std::isfinite(value)) fail_file(source_name(mesh), "face " + std::to_string(t) + " has a non-finite area");
                area[t - first] = value;
            }
        });
        visit(first, std::span<const double>(area.data(), count));
    }
}

// The sum of the triangles' areas, added in triangle order (so the same on any core count).
double total_area_in_order(const Mesh& mesh) {
    double sum = 0.0;
    for_each_area_block(mesh, [&](size_t, std::span<const double> areas) {
        for (double v : areas) sum += v;
    });
    return sum;
}

// The coarse class after its own relaxation (stipple_classes.hpp): triangle t's coarse stipples are
// positions[first[t], first[t + 1]).
struct RelaxedCoarseClass {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> first;  // by triangle, size triangles + 1
};

// Point k of triangle t's stratified sequence (see the top of this file): the k-th point of the R2 sequence
// offset by hash(seed, t) and jittered by hash(seed, t, k), folded onto the triangle. With `coarse`, the
// triangle's coarse stipples are where their relaxation left them, and the sequence is offset so that its
// point 0 falls on the first of them: the others keep the sequence's spacing from it. (Offset by the hash
// instead, they lay anywhere about the moved point, and the whole set's relaxation around the fixed class
// needed about two iterations more for the same delta-bar.)
class Stratification {
public:
    Stratification(const Mesh& mesh, std::span<const uint32_t> first, uint64_t seed, const RelaxedCoarseClass* coarse)
        : mesh_(mesh), first_(first), seed_key_(mix64(seed ^ 0x53544950504C4531ull)), coarse_(coarse) {}

    // Triangle t's sequence: call point(k) for its points.
    struct Triangle {
        glm::dvec3 a{0.0}, b{0.0}, c{0.0};
        uint64_t bits = 0;
        double o1 = 0.0, o2 = 0.0, amount = 0.0;
        const glm::vec3* coarse = nullptr;  // its relaxed coarse stipples, coarse_count of them
        uint32_t coarse_count = 0;

        glm::vec3 point(uint64_t k) const {
            if (k < coarse_count) return coarse[k];
            const uint64_t jitter = mix64(bits ^ mix64(k + 0x4A49545445520000ull));
            double u1 = o1 + double(k) * 0.7548776662466927 + amount * (double(jitter >> 40) * 0x1p-24 - 0.5);
            double u2 = o2 + double(k) * 0.5698402909980532 + amount * (double(jitter & 0xFFFFFF) * 0x1p-24 - 0.5);
            u1 -= std::floor(u1), u2 -= std::floor(u2);
            if (u1 + u2 > 1.0) u1 = 1.0 - u1, u2 = 1.0 - u2;
            return glm::vec3(a + u1 * (b - a) + u2 * (c - a));
        }
    };

    Triangle triangle(size_t t) const {
        Triangle tri;
        tri.bits = mix64(seed_key_ ^ mix64(uint64_t(t) << 32));
        tri.o1 = double(tri.bits >> 40) * 0x1p-24, tri.o2 = double(tri.bits & 0xFFFFFF) * 0x1p-24;
        const uint32_t count = first_[t + 1] - first_[t];
        // Each point jittered by up to a quarter of the sequence's spacing, 1/sqrt(N), either way (see the
        // top of this file).
        tri.amount = kJitter / std::sqrt(double(count));
        tri.a = glm::dvec3(mesh_.positions[mesh_.indices[3 * t]]);
        tri.b = glm::dvec3(mesh_.positions[mesh_.indices[3 * t + 1]]);
        tri.c = glm::dvec3(mesh_.positions[mesh_.indices[3 * t + 2]]);
        if (!coarse_) return tri;
        tri.coarse_count = coarse_->first[t + 1] - coarse_->first[t];
        if (tri.coarse_count == 0) return tri;
        tri.coarse = coarse_->positions.data() + coarse_->first[t];
        // The first coarse stipple's (u, v) on the triangle: the sequence's offset.
        const glm::dvec3 ab = tri.b - tri.a, ac = tri.c - tri.a, ap = glm::dvec3(tri.coarse[0]) - tri.a;
        const double d00 = glm::dot(ab, ab), d01 = glm::dot(ab, ac), d11 = glm::dot(ac, ac);
        const double d20 = glm::dot(ap, ab), d21 = glm::dot(ap, ac), det = d00 * d11 - d01 * d01;
        if (det > 0.0) {
            tri.o1 = std::clamp((d11 * d20 - d01 * d21) / det, 0.0, 1.0);
            tri.o2 = std::clamp((d00 * d21 - d01 * d20) / det, 0.0, 1.0);
        }
        return tri;
    }

    // Every point, by stipple index. A function of the counts, the seed and the coarse class alone, so that
    // the relaxation can have its input again (relax.hpp).
    std::vector<glm::vec3> all() const {
        std::vector<glm::vec3> positions(first_.back());
        // In chunks of stipples, not of triangles: a model of a few large triangles uses every core too.
        parallel_for_chunks(positions.size(), kPointChunk, [&](size_t, size_t begin, size_t end) {
            size_t t = size_t(std::upper_bound(first_.begin(), first_.end(), uint32_t(begin)) - first_.begin()) - 1;
            for (size_t i = begin; i < end; ++t) {
                while (first_[t + 1] <= i) ++t;  // past empty triangles
                const Triangle tri = triangle(t);
                for (; i < std::min<size_t>(end, first_[t + 1]); ++i) positions[i] = tri.point(i - first_[t]);
            }
        });
        return positions;
    }

private:
    const Mesh& mesh_;
    std::span<const uint32_t> first_;
    uint64_t seed_key_;
    const RelaxedCoarseClass* coarse_;
};

std::vector<glm::vec3> stratified_positions(const Mesh& mesh, std::span<const uint32_t> first, uint64_t seed) {
    return Stratification(mesh, first, seed, nullptr).all();
}

// The coarse class of the stratified positions, relaxed as a set of its own at its own spacing.
RelaxedCoarseClass relax_coarse_class(const Mesh& mesh, std::span<const uint32_t> first, uint64_t seed, double spacing,
                                      int iterations, const std::function<void(double)>& progress) {
    const size_t triangles = first.size() - 1;
    RelaxedCoarseClass coarse;
    coarse.first.resize(triangles + 1);
    coarse.first[0] = 0;
    for (size_t t = 0; t < triangles; ++t) coarse.first[t + 1] = coarse.first[t] + coarse_count(first[t + 1] - first[t]);
    const size_t n = coarse.first[triangles];
    if (n == 0) return coarse;
    const Stratification stratification(mesh, first, seed, nullptr);
    auto subset = [&] {  // the coarse stipples of the stratified positions
        std::vector<glm::vec3> out(n);
        parallel_for_chunks(triangles, kTriangleChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t t = begin; t < end; ++t) {
                if (coarse.first[t + 1] == coarse.first[t]) continue;
                const Stratification::Triangle sequence = stratification.triangle(t);
                for (uint32_t k = 0; k < coarse.first[t + 1] - coarse.first[t]; ++k) out[coarse.first[t] + k] = sequence.point(k);
            }
        });
        return out;
    };
    coarse.positions = subset();
    // Its share of the stipples where it lies: triangles of 1 or 2 stipples have none, and a mesh may be
    // mostly such triangles in places (a scan's fine parts beside large flat ones).
    uint64_t around = 0;
    for (size_t t = 0; t < triangles; ++t)
        if (coarse.first[t + 1] > coarse.first[t]) around += first[t + 1] - first[t];
    const double class_spacing = spacing / std::sqrt(double(n) / double(around));
    std::vector<uint32_t> triangle_of(n);
    for (size_t t = 0; t < triangles; ++t)
        std::fill(triangle_of.begin() + coarse.first[t], triangle_of.begin() + coarse.first[t + 1], uint32_t(t));
    relax_stipples(mesh, std::move(triangle_of), coarse.positions, class_spacing, iterations, subset, progress);
    return coarse;
}

// The D_max generation uses for a surface of `area` (Object_max may cap the asked one), and the reference view's
// pixels per unit; both 0 where there is nothing to generate.
struct ReferenceDensity {
    double dmax = 0.0;
    double px_per_unit = 0.0;
};
ReferenceDensity reference_density(const Mesh& mesh, const GenerationParams& params, double area) {
    const float radius = compute_bounding_sphere(mesh).radius;
    if (!(area > 0.0) || !(radius > 0.0f) || params.dmax <= 0.0f || params.max_stipples == 0) return {};
    const double px_per_unit = (kReferenceHeight / 2.0) / radius;
    const double reference_area = area * px_per_unit * px_per_unit;
    return {std::min(static_cast<double>(params.dmax), static_cast<double>(params.max_stipples) / reference_area), px_per_unit};
}

double density_for_area(const Mesh& mesh, const GenerationParams& params, double area) {
    const ReferenceDensity r = reference_density(mesh, params, area);
    return r.dmax * r.px_per_unit * r.px_per_unit;
}

}  // namespace

double stipple_density_per_area(const Mesh& mesh, const GenerationParams& params) {
    check_params(mesh, params);
    return density_for_area(mesh, params, total_area_in_order(mesh));
}

double effective_dmax(const Mesh& mesh, const GenerationParams& params) {
    check_params(mesh, params);
    return reference_density(mesh, params, total_area_in_order(mesh)).dmax;
}

namespace {

// Generation in float multiplies coordinates together (the relaxation's squared distances, and the
// products of two cross products that clamp a stipple into its triangle: a side to the fourth power). Far
// from unit size these overflow or vanish (a triangle of side 1e10 made NaN positions and crashed the
// relaxation; one of 1e-10 underflows), and far from the origin the coordinates lose the spacing's
// digits. Such a mesh is generated as a copy scaled to unit radius about its centre (in double), and the
// stipples are scaled back: the counts, which follow the reference view, do not change.
struct UnitFrame {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

std::optional<UnitFrame> frame_to_rescale(const Mesh& mesh) {
    if (mesh.positions.empty()) return std::nullopt;
    glm::dvec3 lo(mesh.positions[0]), hi(mesh.positions[0]);
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
    UnitFrame frame;
    frame.centre = 0.5 * (lo + hi);
    frame.radius = 0.5 * glm::length(hi - lo);
    const double offset = glm::length(frame.centre);
    const bool unit_size = frame.radius >= 1e-3 && frame.radius <= 1e3;
    if (!(frame.radius > 0.0) || (unit_size && offset <= 100.0 * frame.radius)) return std::nullopt;
    return frame;
}

// Counts by cumulative rounding (see the top of this file): the stipples of triangles 0..t together, for
// every t, into `running_counts` when given; returns the total.
uint64_t cumulative_counts(const Mesh& mesh, double density_per_area, std::span<const float> headroom,
                           uint32_t* running_counts) {
    double running = 0.0;  // S_t; never decreases (E_t >= 0), so neither does its rounding
    for_each_area_block(mesh, [&](size_t first, std::span<const double> areas) {
        for (size_t k = 0; k < areas.size(); ++k) {
            const size_t t = first + k;
            running += density_per_area * areas[k] * (headroom.empty() ? 1.0 : double(headroom[t]));
            if (!running_counts) continue;
            const double rounded = std::floor(running + 0.5);
            if (rounded > double(UINT32_MAX - 1))
                fail_file(source_name(mesh), "more than 2^32 stipples requested; lower D_max or the stipple budget");
            running_counts[t] = static_cast<uint32_t>(rounded);
        }
    });
    const double total = std::floor(running + 0.5);
    if (total > double(UINT32_MAX - 1))
        fail_file(source_name(mesh), "more than 2^32 stipples requested; lower D_max or the stipple budget");
    return static_cast<uint64_t>(total);
}

// The mesh scaled to unit radius about its centre (see UnitFrame).
Mesh unit_copy(const Mesh& mesh, const UnitFrame& frame) {
    Mesh unit;
    unit.source = mesh.source;
    unit.indices = mesh.indices;
    unit.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) unit.positions.push_back(glm::vec3((glm::dvec3(p) - frame.centre) / frame.radius));
    return unit;
}

}  // namespace

uint64_t planned_stipple_count(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom) {
    check_params(mesh, params, headroom);
    if (const std::optional<UnitFrame> frame = frame_to_rescale(mesh))
        return planned_stipple_count(unit_copy(mesh, *frame), params, headroom);
    return cumulative_counts(mesh, density_for_area(mesh, params, total_area_in_order(mesh)), headroom, nullptr);
}

StippleSet generate_stipples(const Mesh& mesh, const GenerationParams& params, std::span<const float> headroom) {
    const auto start = std::chrono::steady_clock::now();
    check_params(mesh, params, headroom);
    if (const std::optional<UnitFrame> frame = frame_to_rescale(mesh)) {
        StippleSet set = generate_stipples(unit_copy(mesh, *frame), params, headroom);
        for (glm::vec3& p : set.positions) p = glm::vec3(frame->centre + glm::dvec3(p) * frame->radius);
        set.density_per_area /= frame->radius * frame->radius;
        set.poisson_radius *= frame->radius;
        set.generation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return set;
    }
    ProgressBar bar("Generating stipples", params.progress);

    const size_t triangles = mesh.triangle_count();
    StippleSet set;
    set.density_per_area = density_for_area(mesh, params, total_area_in_order(mesh));
    if (set.density_per_area > 0.0)
        set.poisson_radius = std::sqrt(2.0 / (std::sqrt(3.0) * set.density_per_area));

    set.first.resize(triangles + 1);
    set.first[0] = 0;
    cumulative_counts(mesh, set.density_per_area, headroom, set.first.data() + 1);
    const size_t n = set.first[triangles];

    auto fill_triangles = [&] {  // the triangle of every stipple, from the counts
        set.triangle.resize(n);
        parallel_for_chunks(triangles, kTriangleChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t t = begin; t < end; ++t)
                std::fill(set.triangle.begin() + set.first[t], set.triangle.begin() + set.first[t + 1], uint32_t(t));
        });
    };
    fill_triangles();
    // With the coarse class (stipple_classes.hpp): each triangle's first stipples of the stratified sequence,
    // whose prefixes are spread over the triangle already, relaxed first as a set of its own. A relaxation
    // feature: without relaxation the flag changes nothing.
    const int relax_its = params.relax_iterations;
    const bool classes = params.coarse_class && relax_its > 0;
    RelaxedCoarseClass coarse;
    if (classes) {
        coarse = relax_coarse_class(mesh, set.first, params.seed, set.poisson_radius, coarse_iterations(relax_its),
                                    [&](double f) { bar.update(0.05 + 0.15 * f); });
        parallel_for_chunks(triangles, kTriangleChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t t = begin; t < end; ++t)
                for (uint32_t k = 0; k < coarse.first[t + 1] - coarse.first[t]; ++k) set.triangle[set.first[t] + k] |= kCoarseClass;
        });
    }
    set.positions = stratified_positions(mesh, set.first, params.seed);
    const double relaxed_from = classes ? 0.20 : 0.05;
    bar.update(relaxed_from);

    // The relaxation takes the triangles, and the order does without them (4 bytes a stipple less at
    // the peaks of both): they are filled again from the counts after. With the class, it sorts the
    // stratified positions and starts each stipple from its place in the sequence around the relaxed class:
    // the stratified positions again give it their order at the end, and the class (3 bytes a stipple, 4 a
    // triangle) is freed before the iterations instead of kept through their peak for it.
    auto start_around_coarse = [&](std::span<glm::vec3> pos, std::span<const uint32_t> original, std::span<const uint32_t> triangle) {
        const Stratification around(mesh, set.first, params.seed, &coarse);
        parallel_for_chunks(pos.size(), kPointChunk, [&](size_t, size_t begin, size_t end) {
            size_t last = SIZE_MAX;
            Stratification::Triangle sequence{};
            for (size_t slot = begin; slot < end; ++slot) {
                const size_t t = triangle[slot] & ~kCoarseClass;
                if (t != last) sequence = around.triangle(t), last = t;
                pos[slot] = sequence.point(original[slot] - set.first[t]);
            }
        });
        coarse = RelaxedCoarseClass();
    };
    relax_stipples(mesh, std::move(set.triangle), set.positions, set.poisson_radius, relax_its,
                   [&] { return stratified_positions(mesh, set.first, params.seed); },
                   [&](double f) { bar.update(relaxed_from + (0.70 - relaxed_from) * f); },  // about the shares of the time
                   classes, classes ? RelaxStart(start_around_coarse) : RelaxStart());
    progressive_order(set.positions, set.first, set.poisson_radius, params.seed,
                      [&](double f) { bar.update(0.70 + 0.30 * f); }, classes);
    fill_triangles();
    bar.finish();

    set.generation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return set;
}

}  // namespace stipple
