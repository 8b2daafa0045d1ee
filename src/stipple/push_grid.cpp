#include "stipple/push_grid.hpp"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#endif

namespace stipple {

namespace {

// nearest[i] = min(nearest[i], |q_i - p|^2) for the slots i in [begin, end). Every variant does the
// same IEEE operations (no FMA): the order does not depend on the machine.
using PushKernel = void (*)(const float*, const float*, const float*, float*, uint32_t, uint32_t, const glm::vec3&);

inline void push_tail(const float* xs, const float* ys, const float* zs, float* nearest, uint32_t i, uint32_t end,
                      const glm::vec3& p) {
    for (; i < end; ++i) {
        const float dx = xs[i] - p.x, dy = ys[i] - p.y, dz = zs[i] - p.z;
        nearest[i] = std::min(nearest[i], (dx * dx + dy * dy) + dz * dz);
    }
}

void push_portable(const float* xs, const float* ys, const float* zs, float* nearest, uint32_t i, uint32_t end,
                   const glm::vec3& p) {
#if defined(__SSE2__)
    const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
    for (; i + 4 <= end; i += 4) {
        const __m128 dx = _mm_sub_ps(_mm_loadu_ps(xs + i), px), dy = _mm_sub_ps(_mm_loadu_ps(ys + i), py),
                     dz = _mm_sub_ps(_mm_loadu_ps(zs + i), pz);
        const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
        _mm_storeu_ps(nearest + i, _mm_min_ps(_mm_loadu_ps(nearest + i), d2));
    }
#endif
    push_tail(xs, ys, zs, nearest, i, end, p);
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define STIPPLE_HAVE_AVX2_PUSH 1
__attribute__((target("avx2"))) void push_avx2(const float* xs, const float* ys, const float* zs, float* nearest,
                                               uint32_t i, uint32_t end, const glm::vec3& p) {
    const __m256 px = _mm256_set1_ps(p.x), py = _mm256_set1_ps(p.y), pz = _mm256_set1_ps(p.z);
    for (; i + 8 <= end; i += 8) {
        const __m256 dx = _mm256_sub_ps(_mm256_loadu_ps(xs + i), px), dy = _mm256_sub_ps(_mm256_loadu_ps(ys + i), py),
                     dz = _mm256_sub_ps(_mm256_loadu_ps(zs + i), pz);
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
        _mm256_storeu_ps(nearest + i, _mm256_min_ps(_mm256_loadu_ps(nearest + i), d2));
    }
    push_tail(xs, ys, zs, nearest, i, end, p);
}
#endif

PushKernel pick_push_kernel() {
#if defined(STIPPLE_HAVE_AVX2_PUSH)
    if (__builtin_cpu_supports("avx2")) return push_avx2;
#endif
    return push_portable;
}

}  // namespace

void PushGrid::push(const glm::vec3& p, float reach) {
    const glm::ivec3 c0 = grid_.cell_of(p - glm::vec3(reach)), c1 = grid_.cell_of(p + glm::vec3(reach));
    // The cells' slots as runs, listed once and then visited: buckets listed twice (shared by two
    // cells) are pushed twice, which a minimum does not mind.
    runs_.clear();
    size_t reached = 0;
    auto add = [&](uint32_t begin, uint32_t end) {
        if (end > begin) runs_.push_back({begin, end}), reached += end - begin;
    };
    for (int z = c0.z; z <= c1.z; ++z)
        for (int y = c0.y; y <= c1.y; ++y) {
            const uint32_t row = grid_.bucket({c0.x, y, z});
            if (grid_.row_is_run(row, c0.x, c1.x)) {
                // Within a window the cells of a row are consecutive buckets.
                add(grid_.bucket_begin(row), grid_.bucket_begin(row + uint32_t(c1.x - c0.x) + 1));
            } else {
                for (int x = c0.x; x <= c1.x; ++x) {
                    const uint32_t b = grid_.bucket({x, y, z});
                    add(grid_.bucket_begin(b), grid_.bucket_end(b));
                }
            }
        }
    // Faces piled in one place (the same triangle many times over) put far more stipples within reach
    // than a surface does: their order is left as it comes rather than cost the pile's square.
    if (reached > kMaxPushed) return;
    static const PushKernel kernel = pick_push_kernel();
    for (const PointGrid::Run& run : runs_) kernel(grid_.xs(), grid_.ys(), grid_.zs(), nearest_.data(), run.begin, run.end, p);
}

}  // namespace stipple
