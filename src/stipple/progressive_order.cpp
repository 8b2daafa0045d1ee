#include "stipple/progressive_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "stipple/point_grid.hpp"
#include "stipple/push_grid.hpp"
#include "stipple/slab_direction.hpp"
#include "stipple/stipple_classes.hpp"

// How the greedy runs on two cores and stays deterministic.
//
// The surface is cut into slabs across one direction (make_units), at least kSearchCap spacings plus two
// unit extents wide, so that only neighbouring slabs interact. Time is cut into
// windows of tau, each 2^(1/8) times the previous one. In a window every slab fills its slots up to the window's
// end, in parallel, seeing every stipple placed before the window anywhere and its own placed in
// the window; between windows each slab takes in what its neighbours placed near it. No state is
// shared between slabs inside a window, so the result does not depend on the thread count, and a
// stipple misses only its neighbour slabs' stipples placed in the same window (about 9% of the
// placed set's density, and only near a slab border). (Ordering even slabs first and odd slabs
// after them, seeing the even ones, left the even ones blind to the odd side: 1.3-2% of a 12-
// triangle cube's prefixes at 1/64-1/256 had a neighbour within half their spacing.)
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
// 24 spacings: a search capped at s reaches the placed set's spacing down to tau = (kSearch / s)^2, 1/256
// here. Large polygons at 1/16 of the frame draw their first 1/400 to 1/1000 (a CAD cylinder's slivers, a
// cube's faces): with 12 (until 2026-12-02) the prefixes below 1/64 were placed blind beyond 12 spacings,
// delta-bar 0.61 at 1/512 on make_cad_cylinder(64) (0.73 now), and its tone fell 9-11% at 1/16 of the size
// (1.03-1.04 max/min now; 16: 1.07-1.08, 20: 1.03-1.04, 32: 1.05). Generation on the 12-triangle cube is
// about 10% slower, the 100k-triangle sphere's unchanged.
constexpr double kSearchCap = 24.0;
constexpr int kSlabs = 24;          // target number of slabs (fewer when they must be wider)
constexpr double kMinSlabSearches = 4.0;  // see make_units
// 64 gave a 12-triangle cube's prefixes delta-bar 0.78 instead of 0.74-0.77 (f = 1/4 to 1/256),
// but cost 50% more ordering time there (each candidate's distance is a cache miss once the slabs
// take turns) and, within the seed-to-seed spread, a little tone at 1/16 of the size.
constexpr uint32_t kMaxCandidates = 16;
// Cells of the push grid, in spacings. Most pushes (tau > 1/4) reach 1.5-3 spacings; with cells
// of 6 they read 1-2 cells per axis, and the few early ones (up to kSearchCap) a handful. Measured
// fastest: cells of 2 spacings made ordering 3x slower (bucket lookups), 8 the same as 6.
constexpr double kPushCell = 6.0;
// What the greedy orders: a triangle's stipples, or the piece of a large triangle's stipples that
// lies in one slab. Slot k of a unit of N stipples appears at tau = (k + 0.5) / N.
struct Unit {
    uint32_t begin, end;  // its stipples: positions_[begin, end)
    uint32_t triangle;
    uint16_t piece;       // 0: the whole triangle; else 1 + the slab of this piece (at most kSlabs + 1 slabs)
    // Its stipples of the coarse class (stipple_classes.hpp; at most 16), which come first: slots k < coarse
    // choose among them, the later slots among the others.
    uint16_t coarse;
};
static_assert(sizeof(Unit) == 16, "a unit a triangle: kept at 16 bytes where triangles hold a stipple or two");
static_assert(coarse_count(kCoarseClassMaxStipples) <= UINT16_MAX);

class Orderer {
public:
    Orderer(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing, uint64_t seed,
            bool coarse_classes)
        : positions_(positions), first_(first), spacing_(spacing), seed_(seed), coarse_classes_(coarse_classes) {}

    void run(const std::function<void(double)>& progress);

private:
    double search_radius(double tau) const {
        return std::min(kSearch / std::sqrt(tau), kSearchCap) * spacing_;
    }
    // One slab's ordering, kept across windows.
    struct SlabState {
        // The unit (by position in the slab's list) of each slot, in order. A slot's time is
        // (k + 0.5) / N_u, k counted in placed_count: equal fractions give equal doubles (correctly
        // rounded division), so it need not be stored (it would double the list's size).
        std::vector<uint32_t> slots;
        size_t next = 0;                      // the next slot to fill
        std::vector<uint32_t> placed_count;   // k of each unit's next slot, by position in its list
        std::unique_ptr<PushGrid> grid;       // its own stipples
        std::vector<std::pair<glm::vec3, float>> placed_in_window;  // (position, search radius)
    };

    void make_units();
    std::vector<uint32_t> slots_in_order(const std::vector<uint32_t>& units) const;
    void start_slab(size_t slab);
    std::vector<uint32_t> own_stipples(size_t slab) const;
    void fill_slab(size_t slab, double until);
    void take_in_neighbours(size_t slab);
    void finish_slab(size_t slab);
    void place(const Unit& unit, uint32_t k, double tau, SlabState& state);
    void merge_pieces();

    // Read by make_units and start_slab, freed while ordering, written in the new order by finish_slab.
    std::vector<glm::vec3>& positions_;
    // order_[unit.begin + k]: the slot in its slab's PushGrid of the stipple in slot k of the unit
    // (filled slots are final; the others list the unit's stipples not placed yet).
    std::vector<uint32_t> order_;
    std::span<const uint32_t> first_;
    double spacing_;
    uint64_t seed_;
    bool coarse_classes_;
    glm::vec3 dir_{1.0f, 0.0f, 0.0f};  // across the slabs (make_units)
    float along(const glm::vec3& p) const { return glm::dot(p, dir_); }
    std::vector<Unit> units_;                        // by triangle, then piece
    std::vector<std::vector<uint32_t>> slab_units_;  // units per slab
    std::vector<float> slab_lo_, slab_hi_;           // extent of each slab's stipples along dir_
    struct Split {
        uint32_t triangle, first_unit, end_unit;
    };
    std::vector<Split> split_;  // triangles cut into pieces
    std::vector<SlabState> state_;  // by slab
};

void Orderer::run(const std::function<void(double)>& progress) {
    if (positions_.empty()) return;
    make_units();
    const size_t slabs = slab_units_.size();
    state_.resize(slabs);
    parallel_for(slabs, 1, [&](size_t slab) { start_slab(slab); });
    // Every stipple is now in its slab's grid, which is all the ordering reads: the positions are put
    // back from the grids at the end (12 bytes a stipple less while ordering). What only the ordering
    // needs (each stipple's slot, the slots in order, the distances: 12 bytes a stipple) comes after them,
    // and the grids drop their input indices (4 bytes) once the slots name the stipples.
    const size_t count = positions_.size();
    std::vector<glm::vec3>().swap(positions_);
    release_free_memory();  // the positions may lie in the allocator's heap, which keeps them resident
    // Each stipple's grid slot, allocated only now: beside the positions and the grids it made the
    // ordering's start the peak of generation (32 bytes a stipple, and more with the allocator's holes).
    order_.resize(count);
    parallel_for(slabs, 1, [&](size_t slab) {
        SlabState& state = state_[slab];
        const std::vector<uint32_t> own = own_stipples(slab);
        for (uint32_t slot = 0; slot < own.size(); ++slot) order_[own[state.grid->point_of(slot)]] = slot;
        state.grid->release_points();  // slots name the stipples from now on: 4 bytes a stipple less
        state.slots = slots_in_order(slab_units_[slab]);
        state.grid->start_distances();
    });

    // Window w ends at tau = 2^(-w/8); the last (w = 0) takes everything left. The first window
    // ends below the earliest slot, 0.5 / (the largest unit).
    uint32_t largest = 1;
    for (const Unit& unit : units_) largest = std::max(largest, unit.end - unit.begin);
    const int windows = 1 + static_cast<int>(std::ceil(8.0 * std::log2(2.0 * largest)));
    // Largest slabs first, so that a large one does not start last and leave the other cores idle
    // (each window waits for its slowest slab). The order of slabs in a window changes nothing else.
    std::vector<size_t> by_size(slabs);
    for (size_t slab = 0; slab < slabs; ++slab) by_size[slab] = slab;
    std::stable_sort(by_size.begin(), by_size.end(),
                     [&](size_t a, size_t b) { return state_[a].slots.size() > state_[b].slots.size(); });
    for (int w = windows - 1; w >= 0; --w) {
        const double until = w == 0 ? std::numeric_limits<double>::infinity() : std::exp2(-w / 8.0);
        parallel_for(slabs, 1, [&](size_t i) { fill_slab(by_size[i], until); });
        if (slabs > 1) parallel_for(slabs, 1, [&](size_t i) { take_in_neighbours(by_size[i]); });
        // A unit's slots are spread evenly in tau, so by time `until` about that share is placed.
        if (progress) progress(w == 0 ? 1.0 : until);
    }
    // What only the windows needed goes before the positions come back.
    for (SlabState& state : state_) {
        std::vector<uint32_t>().swap(state.slots);
        std::vector<uint32_t>().swap(state.placed_count);
        std::vector<std::pair<glm::vec3, float>>().swap(state.placed_in_window);
        state.grid->release_nearest();
    }
    // Those were blocks of a few MiB a slab between the grids' blocks: the allocator keeps them resident
    // unless asked (core/memory.hpp), and the positions coming back on top of them made the peak of the
    // 8M-stipple dragon's generation (401,000 KiB resident, against 355,000 in the relaxation).
    release_free_memory();
    positions_.resize(count);
    parallel_for(slabs, 1, [&](size_t slab) { finish_slab(slab); });
    std::vector<SlabState>().swap(state_);
    std::vector<uint32_t>().swap(order_);
    merge_pieces();
}

// Slabs across one direction, and the units in each. A slab is at least kSearchCap spacings plus two
// unit extents (along the direction) wide, so that only neighbouring slabs interact. Triangles too long
// along it for slabs of about 1/kSlabs of the object (or kMinSlabSearches search caps) are cut at the
// borders into pieces, each ordered as a unit of its own: without that, a model of a few large triangles
// would be one slab, on one core, with a working set beyond the caches. Which direction, and why it
// follows slivers: stipple/slab_direction.hpp.
void Orderer::make_units() {
    const size_t triangles = first_.size() - 1;
    const SlabRule rule{spacing_, kSearchCap, kSlabs, kMinSlabSearches};
    const SlabDirection choice = choose_slab_direction(positions_, first_, rule);
    dir_ = choice.direction;
    const double wanted = rule.wanted_width(choice.size);
    const float split_extent = rule.split_extent(choice.size);
    float max_extent = 0.0f;  // of the triangles kept whole
    for (size_t t = 0; t < triangles; ++t)
        if (choice.extent[t] <= split_extent) max_extent = std::max(max_extent, choice.extent[t]);
    // `wanted`, but for float rounding of split_extent.
    const double width = std::max(wanted, kSearchCap * spacing_ + 2.0 * max_extent);
    const size_t slabs = std::max<size_t>(1, static_cast<size_t>(std::ceil(choice.size / width)));
    STIPPLE_CHECK(slabs < UINT16_MAX, "progressive_order: a slab index beyond a unit's piece field");
    auto slab_at = [&](double x) { return std::min(slabs - 1, static_cast<size_t>(std::max(0.0, (x - choice.lo) / width))); };
    slab_units_.assign(slabs, {});
    slab_lo_.assign(slabs, std::numeric_limits<float>::infinity());
    slab_hi_.assign(slabs, -std::numeric_limits<float>::infinity());
    auto add_unit = [&](const Unit& unit, size_t slab) {
        slab_units_[slab].push_back(static_cast<uint32_t>(units_.size()));
        units_.push_back(unit);
        for (uint32_t i = unit.begin; i < unit.end; ++i) {
            slab_lo_[slab] = std::min(slab_lo_[slab], along(positions_[i]));
            slab_hi_[slab] = std::max(slab_hi_[slab], along(positions_[i]));
        }
    };
    std::vector<uint32_t> count, coarse;
    std::vector<glm::vec3> sorted;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t b = first_[t], e = first_[t + 1];
        if (b == e) continue;
        const uint32_t coarse_end = b + (coarse_classes_ ? coarse_count(e - b) : 0u);
        if (choice.extent[t] <= split_extent) {
            add_unit({b, e, uint32_t(t), 0, uint16_t(coarse_end - b)}, slab_at(choice.centre[t]));
            continue;
        }
        // Cut: the triangle's stipples grouped by slab (a stable counting sort: each piece's coarse
        // stipples stay first), one unit each.
        count.assign(slabs + 1, 0);
        coarse.assign(slabs, 0);
        for (uint32_t i = b; i < e; ++i) {
            const size_t slab = slab_at(along(positions_[i]));
            ++count[slab + 1];
            if (i < coarse_end) ++coarse[slab];
        }
        for (size_t s = 1; s <= slabs; ++s) count[s] += count[s - 1];
        sorted.resize(e - b);
        std::vector<uint32_t> fill(count.begin(), count.end() - 1);
        for (uint32_t i = b; i < e; ++i) sorted[fill[slab_at(along(positions_[i]))]++] = positions_[i];
        std::copy(sorted.begin(), sorted.end(), positions_.begin() + b);
        const uint32_t first_unit = static_cast<uint32_t>(units_.size());
        for (size_t s = 0; s < slabs; ++s)
            if (count[s + 1] > count[s])
                add_unit({b + count[s], b + count[s + 1], uint32_t(t), uint16_t(s + 1), uint16_t(coarse[s])}, s);
        split_.push_back({uint32_t(t), first_unit, static_cast<uint32_t>(units_.size())});
    }
}

// A cut triangle's order: its pieces' slots by increasing (k + phase) / N_piece, ties by piece.
// Each piece's prefix is spread over the piece, and the triangle's prefix takes about the same
// fraction of every piece (systematic sampling: piece p's share of the first c is within one of
// c N_p / N), so it is spread over the triangle. The phases spread the rounding: with 0.5 for all,
// a prefix shorter than the number of pieces would come from the largest pieces, side by side in
// the middle of the triangle; with phases from the radical inverse of the piece's place along the
// axis, its first stipples come from pieces far apart (the first, the middle one, the quarters...).
// The phases are rotated by an offset of the triangle's own (a golden-ratio step from one triangle to the
// next, from a start that follows the seed): with the same phases in every triangle, long slivers side by
// side (a CAD cylinder's sides, a fan's blades) all took their first stipples from the same pieces, and the
// prefixes they draw at a distance lay in bands across them (a cylinder of 1024 sides read 1.28 max/min
// over a 16x range of size, its rows of pixels up to 2.9 times as dark as each other; until 2026-12-04).
void Orderer::merge_pieces() {
    auto radical_inverse = [](uint32_t r) {
        double value = 0.0, digit = 0.5;
        for (; r != 0; r >>= 1, digit *= 0.5)
            if (r & 1u) value += digit;
        return value;
    };
    parallel_for(split_.size(), 1, [&](size_t i) {
        const Split& split = split_[i];
        const uint32_t pieces = split.end_unit - split.first_unit;
        // Each piece's slots come in increasing order already: merged through a heap of the pieces' next
        // slots, ties to the earlier piece. (A stable sort of every slot, 16 bytes each and as much again
        // for the sort's buffer, made this the peak of generation for a model of one large triangle: 54
        // bytes a stipple, against 36 for the 12-triangle cube, until 2026-12-04.)
        struct Next {
            double tau;
            uint32_t unit, k;
        };
        auto later = [](const Next& a, const Next& b) { return a.tau != b.tau ? a.tau > b.tau : a.unit > b.unit; };
        std::vector<double> phase(pieces);
        const double start = double(mix64(seed_ ^ 0x9E3779B97F4A7C15ull) >> 11) * 0x1p-53;
        const double offset = start + double(split.triangle) * 0.6180339887498949;
        for (uint32_t u = split.first_unit; u < split.end_unit; ++u) {
            double rotated = radical_inverse(u - split.first_unit) + 0.5 / pieces + offset;
            phase[u - split.first_unit] = rotated - std::floor(rotated);  // in [0, 1)
        }
        std::vector<glm::vec3> merged;
        merged.reserve(first_[split.triangle + 1] - first_[split.triangle]);
        std::vector<Next> heap;
        heap.reserve(pieces);
        // The pieces' coarse stipples first, then the others, each merged alike: the triangle's first
        // coarse_count(N) stipples are its coarse class, as a whole triangle's are.
        for (const bool coarse : {true, false}) {
            auto range = [&](const Unit& unit) {
                return coarse ? std::pair{unit.begin, unit.begin + unit.coarse} : std::pair{unit.begin + unit.coarse, unit.end};
            };
            for (uint32_t u = split.first_unit; u < split.end_unit; ++u) {
                const auto [b, e] = range(units_[u]);
                if (e > b) heap.push_back({phase[u - split.first_unit] / (e - b), u, 0});
            }
            std::make_heap(heap.begin(), heap.end(), later);
            while (!heap.empty()) {
                std::pop_heap(heap.begin(), heap.end(), later);
                Next& next = heap.back();
                const auto [b, e] = range(units_[next.unit]);
                merged.push_back(positions_[b + next.k]);
                const uint32_t count = e - b;
                if (++next.k < count) {
                    next.tau = (next.k + phase[next.unit - split.first_unit]) / count;
                    std::push_heap(heap.begin(), heap.end(), later);
                } else {
                    heap.pop_back();
                }
            }
        }
        std::copy(merged.begin(), merged.end(), positions_.begin() + first_[split.triangle]);
    });
}

// The slots of the slab's units by increasing tau = (k + 0.5) / N_u, ties by unit. Without a sort
// over all slots: the units with N stipples share their N tau values, so the slots come from the
// (N, k) classes in tau order, each class listing its units in unit order.
std::vector<uint32_t> Orderer::slots_in_order(const std::vector<uint32_t>& units) const {
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
    std::vector<uint32_t> slots;
    slots.reserve(total);
    for (size_t c = 0; c < classes.size();) {
        size_t d = c + 1;
        while (d < classes.size() && classes[d].tau == classes[c].tau) ++d;
        const size_t from = slots.size();
        for (size_t i = c; i < d; ++i)
            for (uint32_t j = classes[i].begin; j < classes[i].end; ++j) slots.push_back(by_count[j].second);
        // Equal tau from different N (1/2 = 3/6): interleave by unit.
        if (d - c > 1)
            std::sort(slots.begin() + from, slots.end());
        c = d;
    }
    return slots;
}

// The slab's own stipples in a grid (from run() on until finish_slab, order_ names them by grid slot).
void Orderer::start_slab(size_t slab) {
    SlabState& state = state_[slab];
    state.placed_count.assign(slab_units_[slab].size(), 0);
    const std::vector<uint32_t> own = own_stipples(slab);
    std::vector<glm::vec3> points(own.size());
    for (size_t local = 0; local < own.size(); ++local) points[local] = positions_[own[local]];
    state.grid = std::make_unique<PushGrid>(points, static_cast<float>(kPushCell * spacing_));
}

// The slab's stipples, unit after unit: the grid's input order. (Rebuilt when needed rather than
// kept: 4 bytes a stipple for every slab at once.)
std::vector<uint32_t> Orderer::own_stipples(size_t slab) const {
    std::vector<uint32_t> own;
    for (uint32_t u : slab_units_[slab])
        for (uint32_t i = units_[u].begin; i < units_[u].end; ++i) own.push_back(i);
    return own;
}

// Fills the slab's slots with tau <= until.
void Orderer::fill_slab(size_t slab, double until) {
    SlabState& state = state_[slab];
    state.placed_in_window.clear();
    const std::vector<uint32_t>& units = slab_units_[slab];
    for (; state.next < state.slots.size(); ++state.next) {
        const uint32_t local = state.slots[state.next];
        const Unit& unit = units_[units[local]];
        const uint32_t k = state.placed_count[local];
        const double tau = (k + 0.5) / (unit.end - unit.begin);
        if (!(tau <= until)) break;
        place(unit, k, tau, state);
        ++state.placed_count[local];
    }
}

// What the neighbouring slabs placed in the last window, near enough to matter here, counts as
// placed here too.
void Orderer::take_in_neighbours(size_t slab) {
    SlabState& state = state_[slab];
    for (size_t nb : {slab - 1, slab + 1}) {
        if (nb >= state_.size()) continue;  // also catches slab - 1 for slab 0
        for (const auto& [p, reach] : state_[nb].placed_in_window)
            if (along(p) >= slab_lo_[slab] - reach && along(p) <= slab_hi_[slab] + reach) state.grid->push(p, reach);
    }
}

// The slab's stipples back into positions_, each unit's in its new order.
void Orderer::finish_slab(size_t slab) {
    SlabState& state = state_[slab];
    for (uint32_t u : slab_units_[slab])
        for (uint32_t i = units_[u].begin; i < units_[u].end; ++i) positions_[i] = state.grid->position(order_[i]);
    state.grid.reset();
}

// Fills slot k of a unit at time tau: picks the not-yet-placed stipple farthest from every placed
// one (at most kMaxCandidates evaluated), moves it to slot k, and pushes its distance.
void Orderer::place(const Unit& unit, uint32_t k, double tau, SlabState& state) {
    PushGrid& grid = *state.grid;
    const uint32_t base = unit.begin + k;
    // The coarse class first, among themselves (see Unit::coarse).
    const uint32_t remaining = (k < unit.coarse ? unit.begin + unit.coarse : unit.end) - base;
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
            // (offset + m * remaining / kMaxCandidates) modulo remaining: both terms are below remaining,
            // so one subtraction takes the modulo, not a division per candidate. Their distances are
            // fetched before any is read: they lie anywhere in a large triangle's piece, beyond the
            // caches (the 12-triangle cube's ordering at 1.64M stipples took 0.64-0.68 s against
            // 0.75-0.83 s with the divisions and reading each as it came).
            uint32_t candidates[kMaxCandidates];
            for (uint32_t m = 0; m < kMaxCandidates; ++m) {
                const uint64_t at = offset + uint64_t(m) * remaining / kMaxCandidates;
                candidates[m] = uint32_t(at >= remaining ? at - remaining : at);
                grid.prefetch_nearest(order_[base + candidates[m]]);
            }
            for (uint32_t m = 0; m < kMaxCandidates; ++m) score(candidates[m]);
        }
    }
    std::swap(order_[base], order_[base + chosen]);
    const glm::vec3 p = grid.position(order_[base]);
    grid.push(p, s);
    if (state_.size() > 1) state.placed_in_window.push_back({p, s});
}

}  // namespace

void progressive_order(std::vector<glm::vec3>& positions, std::span<const uint32_t> first, double spacing,
                       uint64_t seed, const std::function<void(double)>& progress, bool coarse_classes) {
    if (first.size() < 2 || positions.empty() || !(spacing > 0.0)) return;
    Orderer(positions, first, spacing, seed, coarse_classes).run(progress);
}

}  // namespace stipple
