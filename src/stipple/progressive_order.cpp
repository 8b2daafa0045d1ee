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
// also seeing the already ordered stipples of its two even neighbours, which count as placed when
// its clock passes their appearance time. No state is shared between slabs being ordered at the
// same time, so the result does not depend on the thread count; the slab layout depends only on
// the point set. The cost is near even slabs' borders, whose stipples ignore the odd side (the
// odd side does adapt to them).
//
// The nearest placed stipple counts within s(tau) = min(kSearch * spacing / sqrt(tau),
// kSearchCap * spacing): 1.5 times the spacing of the set placed by time tau. Rather than search
// around each candidate for placed stipples (16 searches per slot on a large triangle), every
// placed stipple pushes its distance to the stipples around it, within its own s(tau): each
// stipple keeps the squared distance to its nearest placed one, and a candidate is scored by one
// read, min(s(tau)^2, that distance). This is exact: a placed stipple farther than its s(tau_p)
// from q is farther than s(tau) for every later tau, so capping hides it either way.

namespace stipple {

namespace {

constexpr double kSearch = 1.5;
constexpr double kSearchCap = 12.0;
constexpr int kSlabs = 24;          // target number of slabs (fewer when triangles are large)
constexpr uint32_t kMaxCandidates = 16;
// Cells of the push grid, in spacings: most pushes (tau > 1/4) reach 1.5-3 spacings, so a push
// reads 2-3 cells per axis; the rare early ones (up to kSearchCap) read more cells.
constexpr double kPushCell = 6.0;

// The own stipples of one slab in a static grid, each with the squared distance to its nearest
// placed stipple. Stipples are named by their slot in the grid (spatial order), so that a push
// writes runs of neighbouring slots rather than scattered memory.
class PushGrid {
public:
    PushGrid(std::span<const glm::vec3> points, float cell) {
        grid_.build(points, cell);
        nearest_.assign(points.size(), std::numeric_limits<float>::max());
        slot_of_.resize(points.size());
        for (uint32_t slot = 0; slot < points.size(); ++slot) slot_of_[grid_.sorted_index(slot)] = slot;
    }

    // The slot of points[i].
    uint32_t slot_of(uint32_t i) const { return slot_of_[i]; }
    // The index in `points` of a slot's stipple.
    uint32_t point_of(uint32_t slot) const { return grid_.sorted_index(slot); }
    float nearest(uint32_t slot) const { return nearest_[slot]; }
    glm::vec3 position(uint32_t slot) const { return grid_.sorted_position(slot); }
    size_t size() const { return nearest_.size(); }

    // nearest = min(nearest, |q - p|^2) for the stipples q of the cells within `reach` of p (a
    // superset of those closer than reach; the extra ones are harmless, see the top of the file).
    void push(const glm::vec3& p, float reach) {
        const glm::ivec3 c0 = grid_.cell_of(p - glm::vec3(reach)), c1 = grid_.cell_of(p + glm::vec3(reach));
        const float *xs = grid_.xs(), *ys = grid_.ys(), *zs = grid_.zs();
        float* nearest = nearest_.data();
        auto visit = [&](uint32_t begin, uint32_t end) {
            uint32_t i = begin;
#if defined(__SSE2__)
            // 4 at a time; the same IEEE operations as the scalar tail.
            const __m128 px = _mm_set1_ps(p.x), py = _mm_set1_ps(p.y), pz = _mm_set1_ps(p.z);
            for (; i + 4 <= end; i += 4) {
                const __m128 dx = _mm_sub_ps(_mm_loadu_ps(xs + i), px), dy = _mm_sub_ps(_mm_loadu_ps(ys + i), py),
                             dz = _mm_sub_ps(_mm_loadu_ps(zs + i), pz);
                const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
                _mm_storeu_ps(nearest + i, _mm_min_ps(_mm_loadu_ps(nearest + i), d2));
            }
#endif
            for (; i < end; ++i) {
                const float dx = xs[i] - p.x, dy = ys[i] - p.y, dz = zs[i] - p.z;
                nearest[i] = std::min(nearest[i], (dx * dx + dy * dy) + dz * dz);
            }
        };
        // Buckets listed twice (shared by two cells) are pushed twice: a minimum does not mind.
        const bool rows = grid_.one_window(c0.x, c1.x);
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y) {
                if (rows) {
                    // Within a window the cells of a row are consecutive buckets.
                    const uint32_t row = grid_.bucket({c0.x, y, z});
                    visit(grid_.bucket_begin(row), grid_.bucket_begin(row + uint32_t(c1.x - c0.x) + 1));
                } else {
                    for (int x = c0.x; x <= c1.x; ++x) {
                        const uint32_t b = grid_.bucket({x, y, z});
                        visit(grid_.bucket_begin(b), grid_.bucket_end(b));
                    }
                }
            }
    }

private:
    PointGrid grid_;
    std::vector<float> nearest_;   // by slot
    std::vector<uint32_t> slot_of_;  // by index in the points given
};

struct Slot {
    double tau;      // (k + 0.5) / N_u: equal fractions give equal doubles (correctly rounded division)
    uint32_t local;  // position of the unit in its slab's list (ascending unit index)
};

// What the greedy orders: a triangle's stipples, or the piece of a large triangle's stipples that
// lies in one slab. Slot k of a unit of N stipples appears at tau = (k + 0.5) / N.
struct Unit {
    uint32_t begin, end;  // its stipples: positions_[begin, end)
    uint32_t triangle;
    uint32_t piece;       // 0: the whole triangle; else 1 + the slab of this piece
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
    void make_units();
    std::vector<Slot> slots_in_order(const std::vector<uint32_t>& units) const;
    void order_slab(size_t slab, bool with_halo);
    void place(const Unit& unit, uint32_t k, double tau, PushGrid& grid);
    void apply_order();
    void merge_pieces();

    // Unchanged until apply_order(): stipples are named by their index here while ordering.
    std::vector<glm::vec3>& positions_;
    // order_[unit.begin + k]: the index in positions_ of slot k of the unit (filled slots are
    // final; the others list the unit's stipples not placed yet). While its slab is ordered, the
    // entries of its units name slots of the slab's PushGrid instead.
    std::vector<uint32_t> order_;
    std::span<const uint32_t> first_;
    double spacing_;
    uint64_t seed_;
    int axis_ = 0;
    std::vector<Unit> units_;                        // by triangle, then piece
    std::vector<std::vector<uint32_t>> slab_units_;  // units per slab
    std::vector<float> slab_lo_, slab_hi_;           // extent of each slab's stipples on the axis
    struct Split {
        uint32_t triangle, first_unit, end_unit;
    };
    std::vector<Split> split_;  // triangles cut into pieces
};

void Orderer::run(const std::function<void(double)>& progress) {
    if (positions_.empty()) return;
    order_.resize(positions_.size());
    make_units();
    std::atomic<size_t> done{0};
    const size_t slabs = slab_units_.size();
    for (int parity = 0; parity < 2; ++parity) {
        std::vector<size_t> batch;
        for (size_t s = parity; s < slabs; s += 2) batch.push_back(s);
        parallel_for(batch.size(), 1, [&](size_t i) {
            order_slab(batch[i], parity == 1);
            if (progress) progress(double(done.fetch_add(1) + 1) / double(slabs));
        });
    }
    apply_order();
    merge_pieces();
}

// Slabs across the longest axis, and the units in each. A slab is at least kSearchCap spacings
// plus two unit extents wide, so that only neighbouring slabs interact. Triangles too large for
// slabs of about 1/kSlabs of the object (or 2 kSearchCap spacings) are cut at the slab borders
// into pieces, each ordered as a unit of its own: without that, a model of a few large triangles
// would be one slab, on one core, with a working set beyond the caches.
void Orderer::make_units() {
    const size_t triangles = first_.size() - 1;
    glm::vec3 lo = positions_[0], hi = positions_[0];
    for (const glm::vec3& p : positions_) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 size = hi - lo;
    axis_ = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);

    // Centroid and extent of each triangle's stipples.
    std::vector<float> centre(triangles, 0.0f), extent(triangles, 0.0f);
    parallel_for_chunks(triangles, 4096, [&](size_t, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const uint32_t b = first_[t], e = first_[t + 1];
            if (b == e) continue;
            glm::vec3 sum(0.0f);
            for (uint32_t i = b; i < e; ++i) sum += positions_[i];
            const glm::vec3 m = sum / float(e - b);
            for (uint32_t i = b; i < e; ++i) extent[t] = std::max(extent[t], glm::length(positions_[i] - m));
            centre[t] = m[axis_];
        }
    });
    const double wanted = std::max(double(size[axis_]) / kSlabs, 2.0 * kSearchCap * spacing_);
    const float split_extent = static_cast<float>(0.5 * (wanted - kSearchCap * spacing_));
    float max_extent = 0.0f;  // of the triangles kept whole
    for (size_t t = 0; t < triangles; ++t)
        if (extent[t] <= split_extent) max_extent = std::max(max_extent, extent[t]);

    const double width = std::max(double(size[axis_]) / kSlabs, kSearchCap * spacing_ + 2.0 * max_extent);
    const size_t slabs = std::max<size_t>(1, static_cast<size_t>(std::ceil(size[axis_] / width)));
    auto slab_at = [&](double x) { return std::min(slabs - 1, static_cast<size_t>(std::max(0.0, (x - lo[axis_]) / width))); };
    slab_units_.assign(slabs, {});
    slab_lo_.assign(slabs, std::numeric_limits<float>::infinity());
    slab_hi_.assign(slabs, -std::numeric_limits<float>::infinity());
    auto add_unit = [&](const Unit& unit, size_t slab) {
        slab_units_[slab].push_back(static_cast<uint32_t>(units_.size()));
        units_.push_back(unit);
        for (uint32_t i = unit.begin; i < unit.end; ++i) {
            slab_lo_[slab] = std::min(slab_lo_[slab], positions_[i][axis_]);
            slab_hi_[slab] = std::max(slab_hi_[slab], positions_[i][axis_]);
        }
    };
    std::vector<uint32_t> count;
    std::vector<glm::vec3> sorted;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t b = first_[t], e = first_[t + 1];
        if (b == e) continue;
        if (extent[t] <= split_extent) {
            add_unit({b, e, uint32_t(t), 0}, slab_at(centre[t]));
            continue;
        }
        // Cut: the triangle's stipples grouped by slab (a stable counting sort), one unit each.
        count.assign(slabs + 1, 0);
        for (uint32_t i = b; i < e; ++i) ++count[slab_at(positions_[i][axis_]) + 1];
        for (size_t s = 1; s <= slabs; ++s) count[s] += count[s - 1];
        sorted.resize(e - b);
        std::vector<uint32_t> fill(count.begin(), count.end() - 1);
        for (uint32_t i = b; i < e; ++i) sorted[fill[slab_at(positions_[i][axis_])]++] = positions_[i];
        std::copy(sorted.begin(), sorted.end(), positions_.begin() + b);
        const uint32_t first_unit = static_cast<uint32_t>(units_.size());
        for (size_t s = 0; s < slabs; ++s)
            if (count[s + 1] > count[s]) add_unit({b + count[s], b + count[s + 1], uint32_t(t), uint32_t(s + 1)}, s);
        split_.push_back({uint32_t(t), first_unit, static_cast<uint32_t>(units_.size())});
    }
}

// positions_[i] = old positions_[order_[i]]: a permutation within each unit, so within each
// triangle, done triangle by triangle.
void Orderer::apply_order() {
    const size_t triangles = first_.size() - 1;
    parallel_for_chunks(triangles, 4096, [&](size_t, size_t begin, size_t end) {
        std::vector<glm::vec3> moved;
        for (size_t t = begin; t < end; ++t) {
            const uint32_t b = first_[t], e = first_[t + 1];
            moved.resize(e - b);
            for (uint32_t i = b; i < e; ++i) moved[i - b] = positions_[order_[i]];
            std::copy(moved.begin(), moved.end(), positions_.begin() + b);
        }
    });
    std::vector<uint32_t>().swap(order_);
}

// A cut triangle's order: its pieces' slots by increasing tau = (k + 0.5) / N_piece, ties by
// piece. Each piece's prefix is spread over the piece, so the triangle's prefix, which takes
// about the same fraction of every piece, is spread over the triangle.
void Orderer::merge_pieces() {
    parallel_for(split_.size(), 1, [&](size_t i) {
        const Split& split = split_[i];
        std::vector<std::pair<double, uint32_t>> slots;  // (tau, index in positions_)
        for (uint32_t u = split.first_unit; u < split.end_unit; ++u) {
            const Unit& unit = units_[u];
            const uint32_t count = unit.end - unit.begin;
            for (uint32_t k = 0; k < count; ++k) slots.push_back({(k + 0.5) / count, unit.begin + k});
        }
        // Stable: equal tau keep the piece order in which they were listed.
        std::stable_sort(slots.begin(), slots.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<glm::vec3> merged(slots.size());
        for (size_t j = 0; j < slots.size(); ++j) merged[j] = positions_[slots[j].second];
        std::copy(merged.begin(), merged.end(), positions_.begin() + first_[split.triangle]);
    });
}

// The slots of the slab's units by increasing tau = (k + 0.5) / N_u, ties by unit. Without a sort
// over all slots: the units with N stipples share their N tau values, so the slots come from the
// (N, k) classes in tau order, each class listing its units in unit order.
std::vector<Slot> Orderer::slots_in_order(const std::vector<uint32_t>& units) const {
    std::vector<std::pair<uint32_t, uint32_t>> by_count;  // (N, local), grouped by N
    by_count.reserve(units.size());
    size_t total = 0;
    for (uint32_t local = 0; local < units.size(); ++local) {
        const uint32_t count = units_[units[local]].end - units_[units[local]].begin;
        by_count.push_back({count, local});
        total += count;
    }
    std::sort(by_count.begin(), by_count.end());
    struct Class {
        double tau;
        uint32_t begin, end;  // its units: by_count[begin, end)
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
        // Equal tau from different N (1/2 = 3/6): interleave by unit.
        if (d - c > 1)
            std::sort(slots.begin() + from, slots.end(), [](const Slot& a, const Slot& b) { return a.local < b.local; });
        c = d;
    }
    return slots;
}

void Orderer::order_slab(size_t slab, bool with_halo) {
    const std::vector<uint32_t>& units = slab_units_[slab];
    const std::vector<Slot> slots = slots_in_order(units);

    // Halo: the ordered stipples of the even neighbours near this slab, with their appearance time.
    std::vector<std::pair<double, uint32_t>> halo;
    if (with_halo) {
        const float reach = static_cast<float>(kSearchCap * spacing_);
        const float lo = slab_lo_[slab] - reach, hi = slab_hi_[slab] + reach;
        for (size_t nb : {slab - 1, slab + 1}) {
            if (nb >= slab_units_.size()) continue;  // also catches slab - 1 for slab 0
            for (uint32_t u : slab_units_[nb]) {
                const uint32_t count = units_[u].end - units_[u].begin;
                for (uint32_t k = 0; k < count; ++k) {
                    const uint32_t id = order_[units_[u].begin + k];
                    const float x = positions_[id][axis_];
                    if (x >= lo && x <= hi) halo.push_back({(k + 0.5) / count, id});
                }
            }
        }
        std::stable_sort(halo.begin(), halo.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    }

    // The own stipples in a grid; order_ names them by grid slot while the slab is ordered.
    std::vector<glm::vec3> own;
    std::vector<uint32_t> index_of_own;  // in positions_
    for (uint32_t u : units)
        for (uint32_t i = units_[u].begin; i < units_[u].end; ++i) own.push_back(positions_[i]), index_of_own.push_back(i);
    PushGrid grid(own, static_cast<float>(kPushCell * spacing_));
    std::vector<glm::vec3>().swap(own);
    for (uint32_t local = 0; local < index_of_own.size(); ++local) order_[index_of_own[local]] = grid.slot_of(local);

    std::vector<uint32_t> placed_count(units.size(), 0);  // k of the next slot, by position in `units`
    size_t next_halo = 0;
    for (const Slot& slot : slots) {
        // The halo's stipples that appeared before (or with) this slot count as placed.
        for (; next_halo < halo.size() && halo[next_halo].first <= slot.tau; ++next_halo)
            grid.push(positions_[halo[next_halo].second], static_cast<float>(search_radius(halo[next_halo].first)));
        place(units_[units[slot.local]], placed_count[slot.local]++, slot.tau, grid);
    }

    // Back from grid slots to indices in positions_.
    for (uint32_t i : index_of_own) order_[i] = index_of_own[grid.point_of(order_[i])];
}

// Fills slot k of a unit at time tau: picks the not-yet-placed stipple farthest from every placed
// one (at most kMaxCandidates evaluated), moves it to slot k, and pushes its distance.
void Orderer::place(const Unit& unit, uint32_t k, double tau, PushGrid& grid) {
    const uint32_t base = unit.begin + k;
    const uint32_t remaining = unit.end - base;
    const float s = static_cast<float>(search_radius(tau));
    uint32_t chosen = 0;
    if (remaining > 1) {
        // Candidates: all remaining ones, or kMaxCandidates spread over them from a hashed offset.
        const float cap = s * s;
        float best = -1.0f;
        auto score = [&](uint32_t candidate) {
            const float d2 = std::min(cap, grid.nearest(order_[base + candidate]));
            if (d2 > best) best = d2, chosen = candidate;  // first on ties: deterministic
        };
        if (remaining <= kMaxCandidates) {
            for (uint32_t m = 0; m < remaining; ++m) score(m);
        } else {
            uint64_t key = mix64(uint64_t(unit.triangle) << 32 | k);
            if (unit.piece != 0) key = mix64(key ^ unit.piece);
            const uint64_t offset = mix64(seed_ ^ key) % remaining;
            for (uint32_t m = 0; m < kMaxCandidates; ++m)
                score(uint32_t((offset + uint64_t(m) * remaining / kMaxCandidates) % remaining));
        }
    }
    std::swap(order_[base], order_[base + chosen]);
    grid.push(grid.position(order_[base]), s);
}

}  // namespace

void progressive_order(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing,
                       uint64_t seed, const std::function<void(double)>& progress) {
    if (first.size() < 2 || positions.empty() || !(spacing > 0.0)) return;
    Orderer(positions, first, spacing, seed).run(progress);
}

}  // namespace stipple
