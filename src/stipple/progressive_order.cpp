#include "stipple/progressive_order.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/hash.hpp"
#include "core/parallel.hpp"
#include "stipple/point_grid.hpp"

// How the greedy runs on two cores and stays deterministic.
//
// The surface is cut into slabs across its longest axis (by triangle centroid), at least
// kSearchCap spacings plus two triangle extents wide, so that only neighbouring slabs interact.
// Even slabs are ordered first, in parallel, each on its own; then odd slabs, in parallel, each
// also seeing the already ordered stipples of its two even neighbours, inserted into its search
// structure when its clock passes their appearance time. No state is shared between slabs being
// ordered at the same time, so the result does not depend on the thread count; the slab layout
// depends only on the point set. The cost is near even slabs' borders, whose stipples ignore the
// odd side (the odd side does adapt to them).
//
// The nearest placed stipple is searched within s(tau) = min(kSearch * spacing / sqrt(tau),
// kSearchCap * spacing): 1.5 times the spacing of the set placed by time tau. Each slab keeps its
// placed stipples in a small hash grid with one level per factor of 2 in s, so a query visits
// only a few cells whatever tau is.

namespace stipple {

namespace {

constexpr double kSearch = 1.5;
constexpr double kSearchCap = 12.0;
constexpr int kSlabs = 24;          // target number of slabs (fewer when triangles are large)
constexpr uint32_t kMaxCandidates = 16;
// Candidates spread over at most this many search radii are scored by one query around all of
// them (each placed stipple read once, tested against all candidates); beyond, by one query per
// candidate. Both give the same result (exact minima); this only picks the cheaper.
constexpr float kSharedQuerySpread = 4.0f;
constexpr int kLevels = 4;          // cell levels: s(tau) from kSearch to 8 * kSearch spacings
// Cells of level l are kCellFactor * s_min(l) wide, where s(tau) < 2 s_min(l) on that level: a
// query reads 2-3 cells per axis. (Smaller cells read fewer stipples but cost more in cell
// lookups, larger ones the reverse; 3 measured fastest.)
constexpr double kCellFactor = 3.0;

// Placed stipples of one slab (and its halo), on kLevels levels of cells of size cell0 * 2^level.
// All stipples that may ever be placed are known beforehand, so each level is a counting-sort
// layout with a fixed capacity per bucket (as in PointGrid); placing a stipple appends it to its
// bucket. A query then reads only placed stipples, from contiguous memory. Buckets shared by
// several cells, or listed twice, only add distance tests: a query takes a minimum.
class LevelGrid {
public:
    LevelGrid(const glm::vec3& origin, double cell0, size_t capacity) {
        for (int l = 0; l < kLevels; ++l) {
            // Coarser levels have fewer occupied cells: fewer buckets.
            hash_[l].init(origin, static_cast<float>(cell0 * double(1 << l)), std::max<size_t>(64, capacity >> (2 * l + 1)));
            start_[l].assign(hash_[l].bucket_count() + 1, 0);
        }
    }

    // First pass: room for p at levels 0..top_level.
    void reserve(const glm::vec3& p, int top_level) {
        for (int l = 0; l <= top_level; ++l) ++start_[l][hash_[l].bucket(hash_[l].cell_of(p)) + 1];
    }
    void finish_reserve() {
        const float far = std::numeric_limits<float>::max();
        for (int l = 0; l < kLevels; ++l) {
            std::vector<uint32_t>& start = start_[l];
            for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
            fill_[l].assign(start.begin(), start.end() - 1);
            const size_t n = start.back();
            // Unfilled room reads as stipples out of reach; padded for 4-wide reads past the end.
            xs_[l].assign(n + 4, far), ys_[l].assign(n + 4, far), zs_[l].assign(n + 4, far);
        }
    }

    // Second pass: p is placed; visible to queries at levels 0..top_level.
    void insert(const glm::vec3& p, int top_level) {
        for (int l = 0; l <= top_level; ++l) {
            const uint32_t slot = fill_[l][hash_[l].bucket(hash_[l].cell_of(p))]++;
            xs_[l][slot] = p.x, ys_[l][slot] = p.y, zs_[l][slot] = p.z;
        }
    }

    // Calls visit(begin, end) for the slots of every bucket of the cells [lo, hi] of `level` that
    // holds placed stipples: slots [begin, end) are placed stipples (coordinates in xs(level)...).
    // Slots just past `end` hold other placed stipples or far-away filler, so reading a few of
    // them (4-wide loads) only adds real, placed stipples to a nearest-distance query.
    template <class Visit>
    void for_each_run(const glm::vec3& lo, const glm::vec3& hi, int level, Visit&& visit) const {
        const CellHash& hash = hash_[level];
        const glm::ivec3 c0 = hash.cell_of(lo), c1 = hash.cell_of(hi);
        const bool rows = hash.one_window(c0.x, c1.x);
        const uint32_t* fill = fill_[level].data();
        const uint32_t* start = start_[level].data();
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y) {
                // Within a window the cells of a row are consecutive buckets.
                const uint32_t row = hash.bucket({c0.x, y, z});
                for (int x = c0.x; x <= c1.x; ++x) {
                    const uint32_t b = rows ? row + uint32_t(x - c0.x) : hash.bucket({x, y, z});
                    if (fill[b] > start[b]) visit(start[b], fill[b]);
                }
            }
    }
    const float* xs(int level) const { return xs_[level].data(); }
    const float* ys(int level) const { return ys_[level].data(); }
    const float* zs(int level) const { return zs_[level].data(); }

private:
    CellHash hash_[kLevels];
    std::vector<uint32_t> start_[kLevels];  // capacity layout: bucket b owns [start[b], start[b+1])
    std::vector<uint32_t> fill_[kLevels];   // bucket b's placed stipples are [start[b], fill[b])
    std::vector<float> xs_[kLevels], ys_[kLevels], zs_[kLevels];
};

// best[j] = min(best[j], |q - c_j|^2) for the candidates c_j in lanes [0, lanes), lanes a
// multiple of 4. Minima are exact whatever the order, so both paths give identical results.
inline void nearest_update(float qx, float qy, float qz, const float* cx, const float* cy, const float* cz, float* best,
                           uint32_t lanes) {
#if defined(__SSE2__)
    const __m128 x = _mm_set1_ps(qx), y = _mm_set1_ps(qy), z = _mm_set1_ps(qz);
    for (uint32_t j = 0; j < lanes; j += 4) {
        const __m128 dx = _mm_sub_ps(_mm_load_ps(cx + j), x), dy = _mm_sub_ps(_mm_load_ps(cy + j), y),
                     dz = _mm_sub_ps(_mm_load_ps(cz + j), z);
        const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
        _mm_store_ps(best + j, _mm_min_ps(_mm_load_ps(best + j), d2));
    }
#else
    for (uint32_t j = 0; j < lanes; ++j) {
        const float dx = cx[j] - qx, dy = cy[j] - qy, dz = cz[j] - qz;
        best[j] = std::min(best[j], (dx * dx + dy * dy) + dz * dz);
    }
#endif
}

// min(best, |q - p|^2) over the stipples q in slots [begin, end) (and possibly a few slots after,
// see LevelGrid::for_each_run); 4 slots at a time with SSE2.
inline float nearest_in_run(const glm::vec3& p, const float* xs, const float* ys, const float* zs, uint32_t begin,
                            uint32_t end, float best) {
#if defined(__SSE2__)
    const __m128 x = _mm_set1_ps(p.x), y = _mm_set1_ps(p.y), z = _mm_set1_ps(p.z);
    __m128 m = _mm_set1_ps(best);
    for (uint32_t i = begin; i < end; i += 4) {
        const __m128 dx = _mm_sub_ps(_mm_loadu_ps(xs + i), x), dy = _mm_sub_ps(_mm_loadu_ps(ys + i), y),
                     dz = _mm_sub_ps(_mm_loadu_ps(zs + i), z);
        m = _mm_min_ps(m, _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz)));
    }
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, m);
    return std::min(std::min(lanes[0], lanes[1]), std::min(lanes[2], lanes[3]));
#else
    for (uint32_t i = begin; i < end; ++i) {
        const float dx = xs[i] - p.x, dy = ys[i] - p.y, dz = zs[i] - p.z;
        best = std::min(best, (dx * dx + dy * dy) + dz * dz);
    }
    return best;
#endif
}

struct Slot {
    double tau;      // (k + 0.5) / N_t: equal fractions give equal doubles (correctly rounded division)
    uint32_t local;  // position of the triangle in its slab's list (ascending triangle index)
};

class Orderer {
public:
    Orderer(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing, uint64_t seed)
        : positions_(positions), first_(first), spacing_(spacing), seed_(seed) {}

    void run(const std::function<void(double)>& progress);

private:
    double search_radius(double tau) const {
        return std::min(kSearch / std::sqrt(tau), kSearchCap) * spacing_;
    }
    // The level l with s(tau) in [2^l, 2^(l+1)) * kSearch spacings, i.e. tau in (4^-(l+1), 4^-l].
    // Its cells (kCellFactor * kSearch spacings * 2^l) are wider than the search radius.
    static int level_of(double tau) {
        static_assert(kLevels == 4 && kSearchCap == 8 * kSearch);
        return tau > 1.0 / 4 ? 0 : tau > 1.0 / 16 ? 1 : tau > 1.0 / 64 ? 2 : 3;
    }
    std::vector<Slot> slots_in_order(const std::vector<uint32_t>& tris) const;
    void order_slab(size_t slab, bool with_halo);
    void place(uint32_t t, uint32_t k, double tau, LevelGrid& grid);

    std::vector<glm::vec3>& positions_;
    std::span<const uint32_t> first_;
    double spacing_;
    uint64_t seed_;
    int axis_ = 0;
    std::vector<std::vector<uint32_t>> slab_triangles_;  // triangles (with stipples) per slab
    std::vector<float> slab_lo_, slab_hi_;               // extent of each slab's stipples on the axis
    glm::vec3 origin_{0.0f};
};

void Orderer::run(const std::function<void(double)>& progress) {
    const size_t triangles = first_.size() - 1;
    const size_t n = positions_.size();
    if (n == 0) return;
    glm::vec3 lo = positions_[0], hi = positions_[0];
    for (const glm::vec3& p : positions_) lo = glm::min(lo, p), hi = glm::max(hi, p);
    origin_ = lo;
    const glm::vec3 size = hi - lo;
    axis_ = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);

    // Centroid and extent of each triangle's stipples.
    std::vector<float> centre(triangles, 0.0f);
    std::vector<float> extent_per_chunk((triangles + 4095) / 4096, 0.0f);
    parallel_for_chunks(triangles, 4096, [&](size_t c, size_t begin, size_t end) {
        float max_extent = 0.0f;
        for (size_t t = begin; t < end; ++t) {
            const uint32_t b = first_[t], e = first_[t + 1];
            if (b == e) continue;
            glm::vec3 sum(0.0f);
            for (uint32_t i = b; i < e; ++i) sum += positions_[i];
            const glm::vec3 m = sum / float(e - b);
            for (uint32_t i = b; i < e; ++i) max_extent = std::max(max_extent, glm::length(positions_[i] - m));
            centre[t] = m[axis_];
        }
        extent_per_chunk[c] = max_extent;
    });
    float max_extent = 0.0f;
    for (float e : extent_per_chunk) max_extent = std::max(max_extent, e);

    const double width = std::max(double(size[axis_]) / kSlabs, kSearchCap * spacing_ + 2.0 * max_extent);
    const size_t slabs = std::max<size_t>(1, static_cast<size_t>(std::ceil(size[axis_] / width)));
    slab_triangles_.assign(slabs, {});
    slab_lo_.assign(slabs, std::numeric_limits<float>::infinity());
    slab_hi_.assign(slabs, -std::numeric_limits<float>::infinity());
    for (size_t t = 0; t < triangles; ++t) {
        if (first_[t] == first_[t + 1]) continue;
        const size_t s = std::min(slabs - 1, static_cast<size_t>(std::max(0.0, (centre[t] - lo[axis_]) / width)));
        slab_triangles_[s].push_back(static_cast<uint32_t>(t));
        for (uint32_t i = first_[t]; i < first_[t + 1]; ++i) {
            slab_lo_[s] = std::min(slab_lo_[s], positions_[i][axis_]);
            slab_hi_[s] = std::max(slab_hi_[s], positions_[i][axis_]);
        }
    }

    std::atomic<size_t> done{0};
    for (int parity = 0; parity < 2; ++parity) {
        std::vector<size_t> batch;
        for (size_t s = parity; s < slabs; s += 2) batch.push_back(s);
        parallel_for(batch.size(), 1, [&](size_t i) {
            order_slab(batch[i], parity == 1);
            if (progress) progress(double(done.fetch_add(1) + 1) / double(slabs));
        });
    }
}

// The slots of the slab's triangles by increasing tau = (k + 0.5) / N_t, ties by triangle. Without
// a sort over all slots: the triangles with N stipples share their N tau values, so the slots come
// from the (N, k) classes in tau order, each class listing its triangles in triangle order.
std::vector<Slot> Orderer::slots_in_order(const std::vector<uint32_t>& tris) const {
    std::vector<std::pair<uint32_t, uint32_t>> by_count;  // (N, local), grouped by N
    by_count.reserve(tris.size());
    size_t total = 0;
    for (uint32_t local = 0; local < tris.size(); ++local) {
        const uint32_t count = first_[tris[local] + 1] - first_[tris[local]];
        by_count.push_back({count, local});
        total += count;
    }
    std::sort(by_count.begin(), by_count.end());
    struct Class {
        double tau;
        uint32_t begin, end;  // its triangles: by_count[begin, end)
    };
    std::vector<Class> classes;
    for (uint32_t b = 0; b < by_count.size();) {
        uint32_t e = b;
        while (e < by_count.size() && by_count[e].first == by_count[b].first) ++e;
        const uint32_t count = by_count[b].first;
        for (uint32_t k = 0; k < count; ++k) classes.push_back({(k + 0.5) / count, b, e});
        b = e;
    }
    std::sort(classes.begin(), classes.end(), [](const Class& a, const Class& b) {
        return a.tau < b.tau || (a.tau == b.tau && a.begin < b.begin);
    });
    std::vector<Slot> slots;
    slots.reserve(total);
    for (size_t c = 0; c < classes.size();) {
        size_t d = c + 1;
        while (d < classes.size() && classes[d].tau == classes[c].tau) ++d;
        const size_t from = slots.size();
        for (size_t i = c; i < d; ++i)
            for (uint32_t j = classes[i].begin; j < classes[i].end; ++j) slots.push_back({classes[i].tau, by_count[j].second});
        // Equal tau from different N (1/2 = 3/6): interleave by triangle.
        if (d - c > 1)
            std::sort(slots.begin() + from, slots.end(), [](const Slot& a, const Slot& b) { return a.local < b.local; });
        c = d;
    }
    return slots;
}

void Orderer::order_slab(size_t slab, bool with_halo) {
    const std::vector<uint32_t>& tris = slab_triangles_[slab];
    size_t own = 0;
    for (uint32_t t : tris) own += first_[t + 1] - first_[t];
    const std::vector<Slot> slots = slots_in_order(tris);

    // Halo: the ordered stipples of the even neighbours near this slab, with their appearance time.
    std::vector<std::pair<double, glm::vec3>> halo;
    if (with_halo) {
        const float reach = static_cast<float>(kSearchCap * spacing_);
        const float lo = slab_lo_[slab] - reach, hi = slab_hi_[slab] + reach;
        for (size_t nb : {slab - 1, slab + 1}) {
            if (nb >= slab_triangles_.size()) continue;  // also catches slab - 1 for slab 0
            for (uint32_t t : slab_triangles_[nb]) {
                const uint32_t count = first_[t + 1] - first_[t];
                for (uint32_t k = 0; k < count; ++k) {
                    const glm::vec3& p = positions_[first_[t] + k];
                    if (p[axis_] >= lo && p[axis_] <= hi) halo.push_back({(k + 0.5) / count, p});
                }
            }
        }
        std::stable_sort(halo.begin(), halo.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    }

    LevelGrid grid(origin_, kCellFactor * kSearch * spacing_, own + halo.size());
    // Room for every own stipple at every level (when it will appear is not known yet), and for
    // each halo stipple at the levels its appearance time reaches.
    for (uint32_t t : tris)
        for (uint32_t i = first_[t]; i < first_[t + 1]; ++i) grid.reserve(positions_[i], kLevels - 1);
    for (const auto& [tau, p] : halo) grid.reserve(p, level_of(tau));
    grid.finish_reserve();

    std::vector<uint32_t> placed_count(tris.size(), 0);  // k of the next slot, by position in `tris`
    size_t next_halo = 0;
    for (const Slot& slot : slots) {
        // The halo's stipples that appeared before (or with) this slot become visible.
        for (; next_halo < halo.size() && halo[next_halo].first <= slot.tau; ++next_halo)
            grid.insert(halo[next_halo].second, level_of(halo[next_halo].first));
        place(tris[slot.local], placed_count[slot.local]++, slot.tau, grid);
    }
}

// Fills slot k of triangle t at time tau: picks the not-yet-placed stipple farthest from every
// placed one (at most kMaxCandidates evaluated), moves it to index k, and records it as placed.
void Orderer::place(uint32_t t, uint32_t k, double tau, LevelGrid& grid) {
    const uint32_t base = first_[t] + k;
    const uint32_t remaining = first_[t + 1] - base;
    const int level = level_of(tau);
    uint32_t chosen = 0;
    if (remaining > 1) {
        // Candidates: all remaining ones, or kMaxCandidates spread over them from a hashed offset.
        uint32_t idx[kMaxCandidates];
        uint32_t m = 0;
        if (remaining <= kMaxCandidates) {
            for (; m < remaining; ++m) idx[m] = m;
        } else {
            const uint64_t offset = mix64(seed_ ^ mix64(uint64_t(t) << 32 | k)) % remaining;
            for (; m < kMaxCandidates; ++m) idx[m] = uint32_t((offset + uint64_t(m) * remaining / kMaxCandidates) % remaining);
        }
        const float s = static_cast<float>(search_radius(tau));
        // Candidates in SIMD lanes; unused lanes sit far away and are never chosen.
        alignas(16) float cx[kMaxCandidates], cy[kMaxCandidates], cz[kMaxCandidates], best[kMaxCandidates];
        const uint32_t lanes = (m + 3) / 4 * 4;
        glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
        for (uint32_t j = 0; j < lanes; ++j) {
            const glm::vec3 p = j < m ? positions_[base + idx[j]] : glm::vec3(std::numeric_limits<float>::max());
            cx[j] = p.x, cy[j] = p.y, cz[j] = p.z;
            best[j] = s * s;
            if (j < m) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        const glm::vec3 reach(s);
        const glm::vec3 box = hi - lo;
        const float *xs = grid.xs(level), *ys = grid.ys(level), *zs = grid.zs(level);
        if (std::max({box.x, box.y, box.z}) <= kSharedQuerySpread * s) {
            // Candidates close together: one query around all of them.
            grid.for_each_run(lo - reach, hi + reach, level, [&](uint32_t begin, uint32_t end) {
                for (uint32_t i = begin; i < end; ++i) nearest_update(xs[i], ys[i], zs[i], cx, cy, cz, best, lanes);
            });
        } else {
            // Candidates far apart (a large triangle): one query per candidate.
            for (uint32_t j = 0; j < m; ++j) {
                const glm::vec3 p(cx[j], cy[j], cz[j]);
                grid.for_each_run(p - reach, p + reach, level, [&](uint32_t begin, uint32_t end) {
                    best[j] = nearest_in_run(p, xs, ys, zs, begin, end, best[j]);
                });
            }
        }
        uint32_t arg = 0;
        for (uint32_t j = 1; j < m; ++j)
            if (best[j] > best[arg]) arg = j;  // first on ties: deterministic
        chosen = idx[arg];
    }
    std::swap(positions_[base], positions_[base + chosen]);
    grid.insert(positions_[base], level);
}

}  // namespace

void progressive_order(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing,
                       uint64_t seed, const std::function<void(double)>& progress) {
    if (first.size() < 2 || positions.empty() || !(spacing > 0.0)) return;
    Orderer(positions, first, spacing, seed).run(progress);
}

}  // namespace stipple
