#include "stipple/relax.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#endif

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "stipple/point_grid.hpp"

namespace stipple {

namespace {

// Neighbours within kKernelRadius * spacing repel. Two spacings reach the first ring of a
// hexagonal arrangement (at 1 spacing) and most of the second (at sqrt(3)): enough to even out
// density without the cost of a wider search.
constexpr float kKernelRadius = 2.0f;
// Step per iteration: kStep * spacing * force. Tuned for delta-bar after a few Gauss-Seidel iterations
// (tools/generation_speed: a 100k-triangle UV sphere of 500k stipples, and the 12-triangle cube). With
// the squared falloff, 6 iterations gave 0.860 / 0.870; with the single falloff 5 give 0.857 / 0.870
// (6: 0.868 / 0.881), and the test's sphere of 400k stipples 0.855 against 0.858 (2026-11-28). Steps
// of 0.14 and 0.16, or decreasing from 0.18 to 0.12, were within 0.003 of 0.15; constant 0.2 drops to
// 0.815 (overshoot within a chunk's cells). Jacobi iterations needed 0.1 (0.838 after 6) and overshot
// at 0.12 (0.815).
constexpr float kStep = 0.15f;
// No stipple moves more than this many spacings in one iteration (tames clumps of random points).
constexpr float kMaxStep = 0.5f;
constexpr float kInset = 1e-5f;
// With the coarse class fixed (relax.hpp), it moves in the kFreeIterations after the others' (relax.hpp):
// it was placed for its own spacing, and these even out where it and the others meet. In them it moves at
// kCoarseFreeStep of the others' step, keeping more of its own spacing. On the 100k-triangle sphere of 400k
// stipples (tests/test_generation.cpp), the whole set's delta-bar and the quarter's after 5 + 2, the
// class's own 7 before them: at the full step 0.859 / 0.798, at 0.6 of it 0.855 / 0.809; after 4 + 2 with
// 9 of the class's own (tried before its count followed the relaxation's) at the full step 0.852 / 0.799, at
// half of it 0.847 / 0.816, at 0.6 0.849 / 0.812. With one free iteration the whole set stayed below 0.85
// after 6 and 7 in all.
constexpr float kCoarseFreeStep = 0.6f;
// Buckets per chunk of work, and of Gauss-Seidel (see relax_stipples): fixed, for determinism.
constexpr size_t kChunkBuckets = 2048;
// The grid's buckets per stipple (before rounding up to a power of two). Cells of two spacings hold
// about five stipples, so one bucket a stipple leaves most buckets empty still, and in alternating runs
// it was as fast as two (2026-11-27: the 8M-stipple dragon 8.2-8.4 s either way, the 100k sphere and the
// cube of tools/generation_speed within their noise) for half the bucket table: 2 bytes a stipple of the
// iterations' peak instead of 4-8 with 32-bit starts (issue 17 asks at most 40 bytes a generated stipple).
constexpr double kBucketsPerPoint = 1.0;
// The most neighbours (within the 27 cells around a stipple) a stipple is relaxed among. A surface
// through them holds about 40-70 stipples, a crumpled one a few times that; more means faces piled on
// each other, which relaxing cannot even out.
constexpr size_t kMaxNeighbours = 4096;
// Below this many stipples a triangle on average, the sweep fetches triangles' corners ahead (see
// relax_stipples): the 1M-triangle sphere of 500k stipples (0.5 a triangle) relaxed 22% faster, the
// 871k-triangle dragon of 734k stipples 15% and of 8M stipples (9 a triangle) 1-6%; on models of
// hundreds of stipples a triangle it changed nothing.
constexpr size_t kStipplesPerTriangleToPrefetch = 16;
// Stipples per chunk of the copies into and out of the spatial order.
constexpr size_t kCopyChunk = size_t(1) << 16;

// Positions by slot of a chunk's own points (slots [begin, begin + size) of the grid), as they move
// during an iteration, padded by a SIMD width of points out of reach like the grid's arrays.
struct OwnSlots {
    std::vector<float> x, y, z;
    uint32_t begin = 0, end = 0;

    void load(const PointGrid& grid, uint32_t first, uint32_t last) {
        begin = first, end = last;
        const size_t n = last - first;
        const float far = std::numeric_limits<float>::max();
        x.assign(grid.xs() + first, grid.xs() + last), y.assign(grid.ys() + first, grid.ys() + last);
        z.assign(grid.zs() + first, grid.zs() + last);
        x.resize(n + PointGrid::kPad, far), y.resize(n + PointGrid::kPad, far), z.resize(n + PointGrid::kPad, far);
    }
    bool owns(uint32_t slot) const { return slot >= begin && slot < end; }
    void set(uint32_t slot, const glm::vec3& p) { x[slot - begin] = p.x, y[slot - begin] = p.y, z[slot - begin] = p.z; }
};

// The candidates of one cell: the points of its 27-cell neighbourhood, copied into dense arrays
// (shared by all the cell's points) and padded to whole 8-lane blocks with points out of reach.
// Dense blocks keep the kernel a single loop with no partial blocks; it costs an instruction per
// candidate per SIMD lane, so that is what matters. The chunk's own points are copied as they are
// now (OwnSlots), the others as they were when the iteration began (the grid).
struct Candidates {
    std::vector<float> x, y, z;
    size_t count = 0;  // a multiple of kLanes
    // Where each run's points start in the arrays, to update a point that moves (see relax_stipples): up
    // to 27 runs of the neighbourhood, and one more each where the chunk's own slots begin and end.
    static constexpr int kMaxRuns = 27 + 2;
    PointGrid::Run runs[kMaxRuns];
    uint32_t run_start[kMaxRuns];
    int run_count = 0;
    int last_run = 0;

    void gather(const PointGrid& grid, const OwnSlots& own, const PointGrid::Run* in, int in_count) {
        // Runs split where the chunk's own slots begin and end, so that each part has one source.
        run_count = 0, last_run = 0;
        for (int r = 0; r < in_count; ++r) {
            uint32_t begin = in[r].begin;
            const uint32_t end = in[r].end;
            for (const uint32_t cut : {own.begin, own.end})
                if (cut > begin && cut < end) runs[run_count++] = {begin, cut}, begin = cut;
            if (begin < end) runs[run_count++] = {begin, end};
        }
        size_t n = 0;
        for (int r = 0; r < run_count; ++r) n += runs[r].end - runs[r].begin;
        count = (n + kLanes - 1) / kLanes * kLanes;
        // Room for a whole block past the end: runs are copied in blocks of kLanes that may overrun.
        if (x.size() < count + kLanes) {
            const size_t size = 2 * count + kLanes;
            x.resize(size), y.resize(size), z.resize(size);
        }
        size_t i = 0;
        // Runs are a few points long: blocks of kLanes floats copied inline (a library copy per run and
        // axis cost more in calls than in bytes). Reading up to kLanes - 1 points past a run stays within
        // the padding of the grid (PointGrid::kPad) or of the own slots; what lands past the run is
        // overwritten by the next run or by the padding below.
        static_assert(PointGrid::kPad >= kLanes - 1, "block copies read past the last run");
        for (int r = 0; r < run_count; ++r) {
            const uint32_t begin = runs[r].begin, length = runs[r].end - runs[r].begin;
            const bool mine = own.owns(begin);
            const float *sx = mine ? own.x.data() + (begin - own.begin) : grid.xs() + begin;
            const float *sy = mine ? own.y.data() + (begin - own.begin) : grid.ys() + begin;
            const float *sz = mine ? own.z.data() + (begin - own.begin) : grid.zs() + begin;
            float *dx = x.data() + i, *dy = y.data() + i, *dz = z.data() + i;
            for (uint32_t k = 0; k < length; k += kLanes) {
                std::memcpy(dx + k, sx + k, kLanes * sizeof(float));
                std::memcpy(dy + k, sy + k, kLanes * sizeof(float));
                std::memcpy(dz + k, sz + k, kLanes * sizeof(float));
            }
            run_start[r] = uint32_t(i);
            i += length;
        }
        for (; i < count; ++i) x[i] = y[i] = z[i] = std::numeric_limits<float>::max();
    }

    // The point in `slot` has moved to p (it is among the candidates: its own cell is gathered). The
    // points of a cell follow each other in one run: the last one found is tried first. A point whose
    // position is not a number has a cell of its own that gathers none of it: nothing to update then.
    void update(uint32_t slot, const glm::vec3& p) {
        if (!(last_run < run_count && slot >= runs[last_run].begin && slot < runs[last_run].end)) {
            int found = -1;
            for (int r = 0; r < run_count; ++r)
                if (slot >= runs[r].begin && slot < runs[r].end) found = r;
            if (found < 0) return;
            last_run = found;
        }
        const size_t at = run_start[last_run] + (slot - runs[last_run].begin);
        x[at] = p.x, y[at] = p.y, z[at] = p.z;
    }

    static constexpr size_t kLanes = 8;
};

// The force on p from the candidates: the sum over those q closer than h of
//   h (1 - d^2/h^2) / d^2 * (p - q),   d = |p - q|,
// a push away from q of strength h/d (1 - d^2/h^2): like 1/d when close, 0 at h. It needs no square
// root, only a division. Until 2026-11-28 the falloff was squared, (1 - d^2/h^2)^2, smooth at h; the
// single falloff pushes harder at the first ring of neighbours (at one spacing, h/2: 0.75 of 1/d
// against 0.56), which is what evens out the nearest-neighbour distances, so one iteration fewer
// reaches the same delta-bar (relax_iterations' default went from 6 to 5; see kStep).
//
// Candidate i is summed in lane i % 8 and the lanes are added in a fixed order at the end; AVX2
// (when the CPU has it), SSE2 and plain C++ all do exactly these IEEE operations (no FMA), so the
// result is the same on every machine and for every thread count.
struct Lanes {
    alignas(32) float x[8], y[8], z[8];
    glm::vec3 total() const {
        auto sum = [](const float* v) { return ((v[0] + v[1]) + (v[2] + v[3])) + ((v[4] + v[5]) + (v[6] + v[7])); };
        return {sum(x), sum(y), sum(z)};
    }
};

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define STIPPLE_HAVE_AVX2_KERNEL 1
__attribute__((target("avx2"))) glm::vec3 repulsion_avx2(const glm::vec3& p, const Candidates& c, float h) {
    const __m256 vx = _mm256_set1_ps(p.x), vy = _mm256_set1_ps(p.y), vz = _mm256_set1_ps(p.z);
    const __m256 vh = _mm256_set1_ps(h), vh2 = _mm256_set1_ps(h * h), vinv_h2 = _mm256_set1_ps(1.0f / (h * h));
    const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps();
    __m256 fx = zero, fy = zero, fz = zero;
    for (size_t j = 0; j < c.count; j += 8) {
        const __m256 dx = _mm256_sub_ps(vx, _mm256_loadu_ps(&c.x[j]));
        const __m256 dy = _mm256_sub_ps(vy, _mm256_loadu_ps(&c.y[j]));
        const __m256 dz = _mm256_sub_ps(vz, _mm256_loadu_ps(&c.z[j]));
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
        // d2 > 0 skips the point itself (and exact duplicates, which have no direction).
        const __m256 inside = _mm256_and_ps(_mm256_cmp_ps(d2, vh2, _CMP_LT_OQ), _mm256_cmp_ps(d2, zero, _CMP_GT_OQ));
        const __m256 x = _mm256_sub_ps(one, _mm256_mul_ps(d2, vinv_h2));
        // Masked after the division: d2 may be 0 or infinite in lanes outside.
        const __m256 w = _mm256_and_ps(inside, _mm256_div_ps(_mm256_mul_ps(vh, x), d2));
        fx = _mm256_add_ps(fx, _mm256_mul_ps(w, dx));
        fy = _mm256_add_ps(fy, _mm256_mul_ps(w, dy));
        fz = _mm256_add_ps(fz, _mm256_mul_ps(w, dz));
    }
    // Lanes::total's sums in registers (stored and read back lane by lane, they took about a quarter of
    // the kernel's samples): each hadd adds neighbouring lanes within each 128-bit half, so
    // `sums` holds ((v0 + v1) + (v2 + v3)) for x, y, z in its low half and ((v4 + v5) + (v6 + v7)) in
    // its high half, the same IEEE operations in the same order.
    const __m256 sums = _mm256_hadd_ps(_mm256_hadd_ps(fx, fy), _mm256_hadd_ps(fz, fz));
    const __m128 total = _mm_add_ps(_mm256_castps256_ps128(sums), _mm256_extractf128_ps(sums, 1));
    alignas(16) float xyz[4];
    _mm_store_ps(xyz, total);
    return {xyz[0], xyz[1], xyz[2]};
}
#endif

glm::vec3 repulsion_portable(const glm::vec3& p, const Candidates& c, float h) {
    const float h2 = h * h, inv_h2 = 1.0f / h2;
    Lanes lanes;
#if defined(__SSE2__)
    // Lanes 0-3 and 4-7 in two registers each.
    const __m128 vx = _mm_set1_ps(p.x), vy = _mm_set1_ps(p.y), vz = _mm_set1_ps(p.z);
    const __m128 vh = _mm_set1_ps(h), vh2 = _mm_set1_ps(h2), vinv_h2 = _mm_set1_ps(inv_h2);
    const __m128 one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
    __m128 fx[2] = {zero, zero}, fy[2] = {zero, zero}, fz[2] = {zero, zero};
    for (size_t j = 0; j < c.count; j += 8) {
        for (int half = 0; half < 2; ++half) {
            const size_t k = j + 4 * half;
            const __m128 dx = _mm_sub_ps(vx, _mm_loadu_ps(&c.x[k]));
            const __m128 dy = _mm_sub_ps(vy, _mm_loadu_ps(&c.y[k]));
            const __m128 dz = _mm_sub_ps(vz, _mm_loadu_ps(&c.z[k]));
            const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            const __m128 inside = _mm_and_ps(_mm_cmplt_ps(d2, vh2), _mm_cmpgt_ps(d2, zero));
            const __m128 x = _mm_sub_ps(one, _mm_mul_ps(d2, vinv_h2));
            const __m128 w = _mm_and_ps(inside, _mm_div_ps(_mm_mul_ps(vh, x), d2));
            fx[half] = _mm_add_ps(fx[half], _mm_mul_ps(w, dx));
            fy[half] = _mm_add_ps(fy[half], _mm_mul_ps(w, dy));
            fz[half] = _mm_add_ps(fz[half], _mm_mul_ps(w, dz));
        }
    }
    for (int half = 0; half < 2; ++half) {
        _mm_store_ps(lanes.x + 4 * half, fx[half]);
        _mm_store_ps(lanes.y + 4 * half, fy[half]);
        _mm_store_ps(lanes.z + 4 * half, fz[half]);
    }
#else
    for (int l = 0; l < 8; ++l) lanes.x[l] = lanes.y[l] = lanes.z[l] = 0.0f;
    for (size_t j = 0; j < c.count; ++j) {
        const float dx = p.x - c.x[j], dy = p.y - c.y[j], dz = p.z - c.z[j];
        const float d2 = (dx * dx + dy * dy) + dz * dz;
        if (d2 > 0.0f && d2 < h2) {
            const float x = 1.0f - d2 * inv_h2;
            const float w = (h * x) / d2;
            lanes.x[j % 8] += w * dx, lanes.y[j % 8] += w * dy, lanes.z[j % 8] += w * dz;
        }
    }
#endif
    return lanes.total();
}

using RepulsionKernel = glm::vec3 (*)(const glm::vec3&, const Candidates&, float);

RepulsionKernel pick_kernel() {
#if defined(STIPPLE_HAVE_AVX2_KERNEL)
    if (__builtin_cpu_supports("avx2")) return repulsion_avx2;
#endif
    return repulsion_portable;
}

// Everything phase 2 needs of a triangle: its corners and unit normal.
struct TriangleFrame {
    glm::vec3 a, b, c, n;
};

TriangleFrame frame_of(const Mesh& mesh, uint32_t t) {
    TriangleFrame f;
    f.a = mesh.positions[mesh.indices[3 * size_t(t)]];
    f.b = mesh.positions[mesh.indices[3 * size_t(t) + 1]];
    f.c = mesh.positions[mesh.indices[3 * size_t(t) + 2]];
    const glm::vec3 n = glm::cross(f.b - f.a, f.c - f.a);
    const float len = glm::length(n);
    f.n = len > 0.0f ? n / len : glm::vec3(0.0f);
    return f;
}

// The frames of the triangles met last. A cell's stipples come from a few triangles in turn (half the
// stipples of the 8M-stipple dragon changed triangle from the one before), and each frame read the
// triangle's corners from the mesh.
struct FrameCache {
    static constexpr uint32_t kSize = 16;  // a power of two
    uint32_t triangle[kSize];
    TriangleFrame frame[kSize];

    FrameCache() { std::fill(std::begin(triangle), std::end(triangle), UINT32_MAX); }
    const TriangleFrame& get(const Mesh& mesh, uint32_t t) {
        const uint32_t at = t & (kSize - 1);
        if (triangle[at] != t) triangle[at] = t, frame[at] = frame_of(mesh, t);
        return frame[at];
    }
};

}  // namespace

glm::vec3 clamp_into_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // Closest point on a triangle by Voronoi regions (Ericson, Real-Time Collision Detection 5.1.5),
    // returning barycentric coordinates (u, v, w) of a, b, c.
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    glm::vec3 bary;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    const float vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d1 <= 0.0f && d2 <= 0.0f) {
        bary = {1, 0, 0};
    } else if (d3 >= 0.0f && d4 <= d3) {
        bary = {0, 1, 0};
    } else if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
        const float v = d1 / (d1 - d3);
        bary = {1 - v, v, 0};
    } else if (d6 >= 0.0f && d5 <= d6) {
        bary = {0, 0, 1};
    } else if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
        const float w = d2 / (d2 - d6);
        bary = {1 - w, 0, w};
    } else if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        bary = {0, 1 - w, w};
    } else {
        const float sum = va + vb + vc;
        if (!(sum > 0.0f)) return (a + b + c) / 3.0f;  // degenerate triangle
#if defined(__SSE2__)
        // Nearly every relaxed stipple ends here: the divisions side by side, each as exact as alone.
        alignas(16) float quotients[4];
        _mm_store_ps(quotients, _mm_div_ps(_mm_setr_ps(va, vb, vc, 0.0f), _mm_set1_ps(sum)));
        bary = {quotients[0], quotients[1], quotients[2]};
#else
        bary = glm::vec3(va, vb, vc) / sum;
#endif
    }
    bary = glm::max(bary, glm::vec3(kInset));
#if defined(__SSE2__)
    alignas(16) float normalised[4];
    _mm_store_ps(normalised, _mm_div_ps(_mm_setr_ps(bary.x, bary.y, bary.z, 0.0f), _mm_set1_ps(bary.x + bary.y + bary.z)));
    bary = {normalised[0], normalised[1], normalised[2]};
#else
    bary /= bary.x + bary.y + bary.z;
#endif
    return bary.x * a + bary.y * b + bary.z * c;
}

namespace {

// Iterations over stipples in spatial order (pos and tri, slot by slot): each moves away from its neighbours
// within kKernelRadius * spacing, in its triangle's plane, and stays inside its triangle. A stipple whose
// triangle carries kCoarseClass stays where it is (it still pushes the others) when `coarse_fixed`.
// A coarse stipple that is not fixed moves by coarse_step times the others' step.
void iterate(const Mesh& mesh, std::vector<glm::vec3>& pos, const std::vector<uint32_t>& tri, float s, int iterations,
             bool coarse_fixed, const std::function<void(double)>& progress, float coarse_step = 1.0f) {
    const float h = kKernelRadius * s;
    const size_t n = pos.size();
    static const RepulsionKernel kernel = pick_kernel();
    // The triangles' corners of the stipples a few slots ahead, fetched early when most stipples start a
    // triangle of their own (the frame cache then misses, and its reads of the mesh, scattered over
    // tens of MiB on a fine mesh, were a fifth of the sweep's time on a sphere of 1M triangles and 500k
    // stipples). Two steps: the corner indices first, then the corners they name. Where triangles hold
    // many stipples each the cache hits and this would be work for nothing.
    const bool prefetch_frames = mesh.triangle_count() * kStipplesPerTriangleToPrefetch > n;
    constexpr uint32_t kAheadIndices = 16, kAheadCorners = 8;
    const uint32_t keep = coarse_fixed ? kCoarseClass : 0u;
    PointGrid grid;
    for (int it = 0; it < iterations; ++it) {
        // Gauss-Seidel within fixed chunks of buckets: a stipple moves at once, and the later stipples
        // of its chunk see it where it went; stipples of other chunks are seen where they were when the
        // iteration began (the grid holds a copy). Chunks are fixed ranges of buckets, so the result
        // does not depend on the thread count or on the order in which chunks run. Seeing its
        // neighbours' moves keeps close pairs from both jumping apart at once (the overshoot that
        // bounds a Jacobi step): on a 100k-triangle sphere, delta-bar 0.858 after 6 iterations
        // against Jacobi's 0.838; the 8M-stipple dragon's generation takes about 5% longer (the chunk's
        // own copy of its points, and keeping the gathered candidates up to date). Chunks are thin
        // slabs of a hash window (2 of its 32 layers of cells at 400k stipples): in a prototype, blocks
        // of 8x8x8 cells and a single chunk gave the same figure, but Jacobi within each cell (the
        // points of a cell moving at once, sharing one gather) lost the gain (0.844).
        grid.build(pos, h, kBucketsPerPoint);

        // Bucket by bucket (spatial order). Consecutive points of the same cell share one gathered
        // set of candidates. Each stipple moves within its triangle's plane and stays inside it.
        parallel_for_chunks(grid.bucket_count(), kChunkBuckets, [&](size_t, size_t begin, size_t end) {
            PointGrid::Run runs[27];
            Candidates candidates;
            OwnSlots own;
            own.load(grid, grid.bucket_begin(uint32_t(begin)), grid.bucket_begin(uint32_t(end)));
            glm::ivec3 gathered(INT32_MIN);
            FrameCache frames;
            const uint32_t last_slot = grid.bucket_begin(uint32_t(end));
            for (size_t b = begin; b < end; ++b) {
                for (uint32_t slot = grid.bucket_begin(uint32_t(b)); slot < grid.bucket_end(uint32_t(b)); ++slot) {
                    if (prefetch_frames) {
                        if (slot + kAheadIndices < last_slot)
                            __builtin_prefetch(&mesh.indices[3 * size_t(tri[grid.sorted_index(slot + kAheadIndices)] & ~kCoarseClass)]);
                        if (slot + kAheadCorners < last_slot) {
                            const uint32_t* corner = &mesh.indices[3 * size_t(tri[grid.sorted_index(slot + kAheadCorners)] & ~kCoarseClass)];
                            __builtin_prefetch(&mesh.positions[corner[0]]);
                            __builtin_prefetch(&mesh.positions[corner[1]]);
                            __builtin_prefetch(&mesh.positions[corner[2]]);
                        }
                    }
                    const uint32_t i = grid.sorted_index(slot);
                    if (tri[i] & keep) continue;
                    // Where the iteration found it: each stipple moves once per iteration.
                    const glm::vec3 p = grid.sorted_position(slot);
                    const glm::ivec3 cell = grid.cell_of(p);
                    if (cell != gathered)
                        gathered = cell, candidates.gather(grid, own, runs, grid.neighbor_runs(cell, runs));
                    // A pile of faces in one place (the same triangle many times over) holds more than the
                    // surface's density: its stipples stay where they are rather than cost their
                    // neighbourhood's square (3,000 copies of a triangle took 80 s for 330k stipples).
                    if (candidates.count > kMaxNeighbours) continue;
                    const glm::vec3 force = kernel(p, candidates, h);
                    const TriangleFrame& f = frames.get(mesh, tri[i] & ~kCoarseClass);
                    glm::vec3 step = force - f.n * glm::dot(f.n, force);
                    step *= kStep * s * ((tri[i] & kCoarseClass) ? coarse_step : 1.0f);
                    const float len = glm::length(step);
                    if (len > kMaxStep * s) step *= kMaxStep * s / len;
                    pos[i] = clamp_into_triangle(p + step, f.a, f.b, f.c);
                    own.set(slot, pos[i]);
                    candidates.update(slot, pos[i]);
                }
            }
        });
        if (progress) progress(double(it + 1) / iterations);
    }
}

}  // namespace

void relax_stipples(const Mesh& mesh, std::vector<uint32_t>&& triangle_of, std::vector<glm::vec3>& positions,
                    double spacing, int iterations, const std::function<std::vector<glm::vec3>()>& input_again,
                    const std::function<void(double)>& progress, bool coarse_fixed, const RelaxStart& start) {
    const size_t n = positions.size();
    if (n < 2 || iterations <= 0 || !(spacing > 0.0)) {
        std::vector<uint32_t>().swap(triangle_of);  // taken either way (the caller rebuilds it)
        return;
    }
    STIPPLE_CHECK(mesh.triangle_count() <= kCoarseClass, "relax_stipples: 2^31 triangles or more");
    const float s = static_cast<float>(spacing);
    const float h = kKernelRadius * s;

    // Work on a copy in the grid's spatial order (one sort up front, undone at the end): points
    // move little per iteration, so later grids come out nearly in input order and every pass
    // below walks memory sequentially instead of jumping between the triangle order and the cell
    // order. One array at a time, so that a stipple never costs more than an iteration's 34-36 bytes
    // (relax.hpp): the caller's positions and triangles, 16, are freed once copied; the positions come
    // back at the end, in the order found by sorting the input again.
    // (Sorting on both cores takes 4 bytes a stipple more, below the iterations' peak here but not at the end.)
    std::vector<uint32_t> original = PointGrid::spatial_order(positions, h, kBucketsPerPoint, true);
    // With `start`, which places every stipple, the given positions only set the order.
    if (start) std::vector<glm::vec3>().swap(positions);
    std::vector<glm::vec3> pos(n);
    if (!start) {
        parallel_for_chunks(n, kCopyChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t slot = begin; slot < end; ++slot) pos[slot] = positions[original[slot]];
        });
        std::vector<glm::vec3>().swap(positions);
    }
    std::vector<uint32_t> tri(n);
    parallel_for_chunks(n, kCopyChunk, [&](size_t, size_t begin, size_t end) {
        for (size_t slot = begin; slot < end; ++slot) tri[slot] = triangle_of[original[slot]];
    });
    std::vector<uint32_t>().swap(triangle_of);  // taken: the caller rebuilds it from the counts
    if (start) start(pos, original, tri);
    std::vector<uint32_t>().swap(original);

    // With the coarse class fixed, `iterations`, then kFreeIterations with it moving.
    const int fixed_iterations = coarse_fixed ? iterations : 0;
    const int total = iterations + (coarse_fixed ? kFreeIterations : 0);
    iterate(mesh, pos, tri, s, fixed_iterations, true, [&](double f) {
        if (progress) progress(f * fixed_iterations / total);
    });
    iterate(mesh, pos, tri, s, total - fixed_iterations, false, [&](double f) {
        if (progress) progress((fixed_iterations + f * (total - fixed_iterations)) / total);
    }, kCoarseFreeStep);
    std::vector<uint32_t>().swap(tri);
    original = PointGrid::spatial_order(input_again(), h, kBucketsPerPoint);
    STIPPLE_CHECK(original.size() == n, "relax_stipples: input_again must return the positions given");
    positions.resize(n);
    parallel_for_chunks(n, kCopyChunk, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) positions[original[i]] = pos[i];
    });
}

}  // namespace stipple
