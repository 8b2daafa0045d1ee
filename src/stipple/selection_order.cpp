#include "stipple/selection_order.hpp"

#include <algorithm>
#include <cmath>

#include "core/hash.hpp"
#include "core/parallel.hpp"
#include "stipple/point_grid.hpp"

namespace stipple {

namespace {

// Ranked centroids in cubic cells of the current level's radius, hashed into buckets as the point
// grids do (stipple/point_grid.hpp: a row of neighbouring cells is a run of neighbouring buckets, so a
// query reads a few cache lines, not 27 scattered ones). Each bucket holds the last centroid inserted
// into it, each centroid the one before it in its bucket. Cells sharing a bucket only add distance
// tests. (A map of vectors per cell made this ranking half of the time to open the 871k-triangle
// dragon, most of it waiting for memory.)
class RankedGrid {
public:
    // At most `capacity` centroids will be inserted, all at or above `origin`.
    RankedGrid(const glm::vec3& origin, float cell, size_t capacity) : radius2_(cell * cell) {
        hash_.init(origin, cell, 2 * capacity);
        last_.assign(hash_.bucket_count(), kNone);
        entries_.reserve(capacity);
    }

    void insert(const glm::vec3& p) {
        const uint32_t bucket = hash_.bucket(hash_.cell_of(p));
        entries_.push_back({p, last_[bucket]});
        last_[bucket] = uint32_t(entries_.size() - 1);
    }

    // Empties the grid, touching only the buckets its centroids went to.
    void clear() {
        for (const Entry& e : entries_) last_[hash_.bucket(hash_.cell_of(e.point))] = kNone;
        entries_.clear();
    }

    // The bucket of p's own cell into the cache ahead of a query or an insertion there (both come in an
    // order that is random in space, each a wait for memory otherwise; prefetching all nine rows of a
    // query, or their first centroids too, measured no better).
    void prefetch(const glm::vec3& p) const { __builtin_prefetch(&last_[hash_.bucket(hash_.cell_of(p))]); }

    size_t size() const { return entries_.size(); }

    float radius2() const { return radius2_; }

    // The squared distance from p to its nearest centroid closer than the radius, or infinity if none
    // is. The nearest rather than the first found: a site rejected now is rejected at the next levels,
    // whose radii are smaller, without a query for as long as its nearest stays within them (see
    // Pending).
    float nearest_within(const glm::vec3& p) const {
        const glm::ivec3 c = hash_.cell_of(p);
        float nearest = INFINITY;
        if (hash_.one_window(c - glm::ivec3(1), c + glm::ivec3(1))) {
            // The rows' first buckets as steps from the corner's (one hash a query instead of nine: most
            // queries find their buckets empty, and the hashing was most of their work).
            const uint32_t corner = hash_.bucket(c - glm::ivec3(1)), mask = uint32_t(hash_.bucket_count() - 1);
            for (uint32_t z = 0; z < 3; ++z)
                for (uint32_t y = 0; y < 3; ++y) {
                    const uint32_t first = corner + y * hash_.y_step() + z * hash_.z_step();
                    for (uint32_t b = first; b < first + 3; ++b) nearest = std::min(nearest, nearest_in(b & mask, p));
                }
            return nearest < radius2_ ? nearest : INFINITY;
        }
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy) {
                const glm::ivec3 row(c.x - 1, c.y + dy, c.z + dz);
                const uint32_t first = hash_.bucket(row);
                if (hash_.row_is_run(first, row.x, c.x + 1)) {
                    for (uint32_t b = first; b < first + 3; ++b) nearest = std::min(nearest, nearest_in(b, p));
                } else {
                    for (int dx = -1; dx <= 1; ++dx)
                        nearest = std::min(nearest, nearest_in(hash_.bucket(row + glm::ivec3(dx + 1, 0, 0)), p));
                }
            }
        return nearest < radius2_ ? nearest : INFINITY;
    }

private:
    static constexpr uint32_t kNone = ~uint32_t(0);
    float nearest_in(uint32_t bucket, const glm::vec3& p) const {
        float nearest = INFINITY;
        for (uint32_t i = last_[bucket]; i != kNone; i = entries_[i].before) {
            const glm::vec3 d = entries_[i].point - p;
            nearest = std::min(nearest, glm::dot(d, d));
        }
        return nearest;
    }
    struct Entry {
        glm::vec3 point;
        uint32_t before;  // the previous centroid in its bucket (one cache line holds both)
    };
    CellHash hash_;
    float radius2_;
    std::vector<uint32_t> last_;   // by bucket: its last centroid
    std::vector<Entry> entries_;   // centroids in insertion order
};

// How many triangles ahead the arrays indexed by triangle are fetched where they are read in the order of
// rank or of area, which is random over the mesh's memory.
constexpr size_t kFetchAhead = 16;

// The largest selection value: values are multiples of 2^-24 below 1.
constexpr float kLastValue = 1.0f - 1.0f / 16777216.0f;

// The facing of a triangle, coarsely: the octant of its normal and the axis along which it is longest (24
// bins). The octant alone put the +x, +y and +z faces of axis-aligned parts in one bin (a zero component
// counts as positive).
constexpr int kFacings = 24;
uint8_t facing_bin(const glm::vec3& n) {
    const glm::vec3 m = glm::abs(n);
    const int axis = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    return uint8_t(3 * (int(n.x < 0.0f) | int(n.y < 0.0f) << 1 | int(n.z < 0.0f) << 2) + axis);
}

// True when the ranks of a class's triangles (by_area[begin, end), in rank order) measurably follow their
// facing: some facing's mean rank lies more than kFacingZ standard errors from the middle. Independent of
// the facing, the mean rank fraction of m of the class's n triangles has mean 1/2 and variance
// (n + 1)(n - m) / (12 n^2 m), at most 1 / (12 m); the bound is used, which understates z where one facing
// holds much of its class (a miss, never a false split). Used by calibrate_per_class, below.
template <class Keyed>
bool ranks_follow_facing(const std::vector<Keyed>& by_area, size_t begin, size_t end,
                         const std::vector<uint8_t>& facings) {
    constexpr double kFacingZ = 5.0;
    const size_t n = end - begin;
    if (n < 64) return false;
    double rank_sum[kFacings] = {}, members[kFacings] = {};
    for (size_t k = begin; k < end; ++k) {
        if (k + kFetchAhead < end) __builtin_prefetch(&facings[by_area[k + kFetchAhead].triangle]);
        const uint8_t f = facings[by_area[k].triangle];
        rank_sum[f] += (double(k - begin) + 0.5) / double(n);
        members[f] += 1.0;
    }
    for (int f = 0; f < kFacings; ++f) {
        const double z = members[f] > 0.0 ? std::abs(rank_sum[f] / members[f] - 0.5) * std::sqrt(12.0 * members[f]) : 0.0;
        if (z > kFacingZ) return true;
    }
    return false;
}

// Sorted as std::sort would, in halves on two cores and merged; for a total order (no two elements equal)
// the result is the one sort's. The 871k-triangle dragon's classes took 0.13 s on one core, 0.08 on two.
template <class T, class Less>
void sort_on_two_cores(std::vector<T>& items, const Less& less) {
    const size_t half = items.size() >= 65536 ? items.size() / 2 : 0;
    parallel_for(half > 0 ? 2 : 1, 1, [&](size_t part) {
        const auto from = items.begin() + std::ptrdiff_t(part == 0 ? 0 : half);
        const auto to = part == 0 && half > 0 ? items.begin() + std::ptrdiff_t(half) : items.end();
        std::sort(from, to, less);
    });
    if (half > 0) std::inplace_merge(items.begin(), items.begin() + std::ptrdiff_t(half), items.end(), less);
}

// Triangles in classes of the same candidate count (below kExactCounts; from there on the area decides
// alone) and about the same area (within kClassRatio of the class's smallest); in each class of n the
// k-th in the order of `scaled` (the blue-noise rank) gets a value in [k / n, (k + 1) / n), at a place
// in that step drawn per triangle. So every class holds exactly uniform values whatever the spread of
// triangle sizes (a lone large triangle among tiny ones included), P(value < p) = p for a triangle of
// any size, and the probabilistic selection's expected ink is the owed ink; within a class the
// blue-noise order is kept, so the selected triangles stay evenly spread.
// The count matters because p is proportional to it (a polygon owes its candidates times the view's
// terms), and the ranks are not independent of it: where triangles hold one or two stipples (a low
// D_max), the first stipples of those with two are placed earlier in the progressive order, and
// ranked earlier as sites. On the bunny at D_max 0.05, classes by area alone gave the triangles with
// two candidates P(value < p) = 1.04-1.09 p and those with one 0.93-0.97 p, and the probabilistic
// regime drew 2.6-3.3% more than it owed framed and at twice the distance (3.7-3.9 standard
// deviations; `stipple tone --dmax 0.05 --regimes`). From kExactCounts candidates on, a count follows
// the area to within 1/16, and a class of one count would hold a triangle or two, whose values would
// keep nothing of the blue-noise order.
// And a class whose ranks measurably follow the facing (facing_bin: the octant of the triangle's normal and
// its longest axis) is made uniform per facing too, for the same reason: p follows the facing (shading, the
// orientation term). Many copies of one small shape turned alike (particles, glyphs, an instanced part,
// whose faces the draw order leaves in the same order in every copy) are ranked within a copy by where each
// face's first stipple lies, which follows the order the faces were placed in, so the faces of one facing
// rank earlier than the others in every copy: a cloud of 100,000 tetrahedra turned about z alone
// (tools/tone_survey_meshes.py g11), its faces facing up 0.91 p below p = 0.2 and those facing down 1.08 p,
// drew 0.92-0.96 of what the probabilistic regime owed (`stipple tone CLOUD.obj --regimes`); 8,000 boxes not
// turned, their faces 0.74-1.28 p by direction, drew 0.71-0.75 of it
// (SelectionValues.UniformForEveryFacingOfRepeatedParts; 0.78-0.86 with bins by octant alone; now 1.000).
// Only such classes: every class split by octant left a scan's classes of a few dozen triangles, whose
// values keep little of the blue-noise order (the bunny's tone at 1/16 of its size fell 5%). The shared
// models' and the default scene's classes read at most 4.6 standard errors over seeds 1-5 (the ogre, seed
// 1; none split: a class split by chance would only lose some of its order); the test's boxes 35 and
// tetrahedra 9.5, the cloud above 14.5; with each copy's faces shuffled the cloud reads 3.7 and is not
// split, keeping a bias of 1-2%.
// Only the triangles for which `calibrated` is set take part (the others keep their values).
void calibrate_per_class(const std::vector<double>& areas, const std::vector<uint32_t>& counts,
                         const std::vector<uint8_t>& facings, const std::vector<double>& scaled,
                         const std::vector<uint8_t>& calibrated, uint64_t seed, std::vector<float>& values) {
    constexpr double kClassRatio = 1.19;  // 2^(1/4): p varies by under 10% across a class
    constexpr uint32_t kExactCounts = 8;
    // The sort keys beside their triangles: sorting indices that compare through the arrays read one
    // random cache line per comparison (most of this function's time on the 871k-triangle dragon).
    struct Keyed {
        uint32_t count_class;
        uint32_t triangle;
        double key;  // the area, then the blue-noise rank scaled by it
    };
    std::vector<Keyed> by_area;
    by_area.reserve(areas.size());
    for (size_t t = 0; t < areas.size(); ++t)
        if (calibrated[t]) by_area.push_back({std::min(counts[t], kExactCounts), uint32_t(t), areas[t]});
    const size_t count = by_area.size();
    auto by_class_and_area = [](const Keyed& a, const Keyed& b) {
        if (a.count_class != b.count_class) return a.count_class < b.count_class;
        return a.key < b.key || (a.key == b.key && a.triangle < b.triangle);
    };
    sort_on_two_cores(by_area, by_class_and_area);  // the order is total: triangles break ties
    const uint64_t key = mix64(seed ^ 0x53454C4543540001ull);
    // The classes' bounds first (each starts at a triangle whose area sets its limit), then the
    // classes on both cores: each writes its own range and its own triangles' values.
    std::vector<size_t> class_begin;
    for (size_t begin = 0; begin < count;) {
        class_begin.push_back(begin);
        size_t end = begin;
        const uint32_t class_count = by_area[begin].count_class;
        const double limit = by_area[begin].key * kClassRatio;
        while (end < count && by_area[end].count_class == class_count && by_area[end].key <= limit) ++end;
        begin = end;
    }
    class_begin.push_back(count);
    parallel_for(class_begin.size() - 1, 1, [&](size_t c) {
        const size_t begin = class_begin[c], end = class_begin[c + 1];
        for (size_t k = begin; k < end; ++k) {
            if (k + kFetchAhead < end) __builtin_prefetch(&scaled[by_area[k + kFetchAhead].triangle]);
            by_area[k].key = scaled[by_area[k].triangle];
        }
        std::sort(by_area.begin() + std::ptrdiff_t(begin), by_area.begin() + std::ptrdiff_t(end),
                  [](const Keyed& a, const Keyed& b) {
                      return a.key < b.key || (a.key == b.key && a.triangle < b.triangle);
                  });
        // Values uniform over [from, to) of by_area, in its order.
        auto assign = [&](size_t from, size_t to) {
            const double n = double(to - from);
            for (size_t k = from; k < to; ++k) {
                if (k + kFetchAhead < to) __builtin_prefetch(&values[by_area[k + kFetchAhead].triangle], 1);
                const uint32_t t = by_area[k].triangle;
                const double within = double(mix64(key ^ t) >> 11) * 0x1p-53;
                const double value = std::min((double(k - from) + within) / n, double(kLastValue));
                values[t] = float(std::floor(value * 16777216.0)) * (1.0f / 16777216.0f);  // a multiple of 2^-24
            }
        };
        if (!ranks_follow_facing(by_area, begin, end, facings)) return assign(begin, end);
        // Each facing on its own, in the class's order.
        std::stable_sort(by_area.begin() + std::ptrdiff_t(begin), by_area.begin() + std::ptrdiff_t(end),
                         [&](const Keyed& a, const Keyed& b) { return facings[a.triangle] < facings[b.triangle]; });
        for (size_t from = begin; from < end;) {
            size_t to = from + 1;
            while (to < end && facings[by_area[to].triangle] == facings[by_area[from].triangle]) ++to;
            assign(from, to);
            from = to;
        }
    });
}

// The order in which the dart throwing below offers the triangles' sites: each arrives at u / w, u uniform per
// triangle and w its weight, the candidate count where counts are known (p, the probability of §2.3's
// selection, is proportional to it) and the area otherwise. By any time x a triangle has been offered with
// probability min(1, x w): each level of the ranking, which examines the earliest arrivals, sees as many sites
// per unit of area where the triangles are small as where they are large, and where a level's radius leaves
// room for one site among several triangles, the one that owes more is the likelier to be offered first
// (of two, weights w_i > w_j: first with probability 1 - w_j / (2 w_i)). So a triangle reaches an early rank
// about in proportion to what it owes, whatever the sizes beside it, and the triangles a small p selects in
// each class of size (calibrate_per_class) are the early ranks of one blue-noise order. Offered in a random
// order (until 2026-12-06), a room went to any of the triangles in it alike: a class's early ranks fell where
// its triangles were many rather than large, a different share in each class, and where neighbouring
// triangles differ widely in area (an isosurface's slivers beside its full triangles) the selected triangles
// of different classes fell on each other as if thrown at random. The metaballs of
// tools/tone_survey_meshes.py g03b at 1/16 of the frame height: their dots' ink over their unshared ink 0.903
// (a sphere's 0.94), now 0.935; their tone over a 16-fold range of size 1.049 / 1.059 (seeds 1-3, two views),
// now 1.020 / 1.021; the gyroid (g03) 1.053 / 1.050, now 1.039 / 1.044 (docs/paper-reading.md, §2.3 regime
// (b)). Where the triangles are alike in size the order is a random one, as before. A triangle of no weight
// (no candidate: p = 0) comes after all others, in the mesh's order, so that it takes no room from the others:
// it never draws, and its value is not ranked at all (selection_values_at).
std::vector<uint32_t> arrival_order(const std::vector<double>& areas, const std::vector<uint32_t>& counts,
                                    uint64_t seed, size_t& weighted) {
    const size_t count = areas.size();
    const bool counted = std::any_of(counts.begin(), counts.end(), [](uint32_t c) { return c > 0; });
    struct Arrival {
        double time;
        uint32_t triangle;
    };
    const uint64_t key = mix64(seed ^ 0x9E3779B97F4A7C15ull);
    std::vector<Arrival> arrivals;
    arrivals.reserve(count);
    std::vector<uint32_t> weightless;
    for (size_t t = 0; t < count; ++t) {
        const double u = (double(mix64(key ^ t) >> 11) + 0.5) * 0x1p-53;  // in (0, 1)
        const double weight = counted ? double(counts[t]) : areas[t];
        if (!(weight > 0.0) || !std::isfinite(u / weight))
            weightless.push_back(uint32_t(t));
        else
            arrivals.push_back({u / weight, uint32_t(t)});
    }
    auto earlier = [](const Arrival& a, const Arrival& b) {
        return a.time < b.time || (a.time == b.time && a.triangle < b.triangle);
    };
    sort_on_two_cores(arrivals, earlier);  // a total order: triangles break ties
    std::vector<uint32_t> order(count);
    weighted = arrivals.size();
    for (size_t i = 0; i < weighted; ++i) order[i] = arrivals[i].triangle;
    std::copy(weightless.begin(), weightless.end(), order.begin() + std::ptrdiff_t(weighted));
    return order;
}

glm::vec3 centroid(const Mesh& mesh, size_t t) {
    return (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
            mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
}

// The values, from the blue-noise order of one site per triangle; `counts` are the triangles' candidate
// counts (all 0 where they are not known), which the values are made uniform within.
std::vector<float> selection_values_at(const Mesh& mesh, std::vector<glm::vec3>&& sites,
                                       const std::vector<uint32_t>& counts, uint64_t seed) {
    const size_t count = mesh.triangle_count();
    std::vector<float> values(count, 0.0f);
    if (count == 0) return values;
    const double area = std::max(total_area(mesh), 1e-30);
    glm::vec3 lowest = sites[0];
    for (const glm::vec3& c : sites) lowest = glm::min(lowest, c);
    std::vector<double> areas(count);
    for (size_t t = 0; t < count; ++t) areas[t] = triangle_area(mesh, t);  // in the mesh's order: its memory in order

    // A site waiting to be ranked, with the squared distance to a ranked centroid near it (infinity
    // when none is known): once a site is rejected for a centroid at distance d, it is rejected at every
    // later level whose radius exceeds d, as the centroid stays ranked. Those tests (40% of the 3.3M
    // on the 871k-triangle dragon, a wait for memory each) are skipped; the result is the same.
    struct Pending {
        uint32_t triangle;
        float near2;
    };
    // Only the triangles of some weight take part: one of none (p = 0) ranked among them would take a room
    // that a triangle which draws needs, and at the last levels, where the rejected sites wait behind the
    // unexamined ones, the weightless ones' sites came first (a plane at D_max 0.01, four triangles of five
    // without a candidate: 55% of the first 1,000 ranks were theirs). They follow all others.
    std::vector<Pending> pending;
    std::vector<uint32_t> weightless;
    {
        size_t weighted = 0;
        // The sort's memory is freed before the ranking's arrays are made.
        const std::vector<uint32_t> order = arrival_order(areas, counts, seed, weighted);
        pending.resize(weighted);
        for (size_t i = 0; i < weighted; ++i) pending[i] = {order[i], INFINITY};
        weightless.assign(order.begin() + std::ptrdiff_t(weighted), order.end());
    }
    size_t head = 0;  // pending[head..] wait, in order: moving the head, not the sites, per level

    std::vector<uint32_t> ranked;
    ranked.reserve(count);
    // The ranked sites by rank, read in order to fill each level's grid; and how far ahead the sites and the
    // grid's buckets are fetched where they are read in the order of arrival, which is random in space.
    std::vector<glm::vec3> ranked_sites;
    ranked_sites.reserve(pending.size());
    constexpr size_t kArrivalAhead = 8;
    // Sites tested against the level's ranked centroids at once, and per chunk of that test.
    constexpr size_t kBlock = 16384, kQueryChunk = 2048;
    std::vector<float> near_ranked(kBlock);
    // Level L aims at 2^L ranked sites: Poisson-disc radius 0.75 x the hexagonal spacing of that
    // many points. Each level examines at most 8x its target, so the whole order costs O(count).
    for (size_t target = 1; target < count && head < pending.size(); target *= 2) {
        float radius = float(0.75 * std::sqrt(2.0 * area / (std::sqrt(3.0) * double(target))));
        const size_t budget = std::min(pending.size() - head, 8 * target);
        RankedGrid grid(lowest, radius, ranked.size() + budget);
        for (size_t r = 0; r < ranked_sites.size(); ++r) {
            if (r + kArrivalAhead < ranked_sites.size()) grid.prefetch(ranked_sites[r + kArrivalAhead]);
            grid.insert(ranked_sites[r]);
        }
        RankedGrid block_grid(lowest, radius, kBlock);
        std::vector<Pending> rejected;
        // Dart throwing in blocks, with the same result as one site after the other: a site near a centroid
        // ranked before its block is rejected whatever its block does, so those tests (nearly all of the
        // time, each a wait for memory) run on every core; then, in order, each remaining site is tested
        // against the centroids its own block has ranked so far, a small grid that stays in the cache.
        const size_t first = head;
        for (size_t block = first; block < first + budget; block += kBlock) {
            const size_t block_end = std::min(first + budget, block + kBlock);
            parallel_for_chunks(block_end - block, kQueryChunk, [&](size_t, size_t begin, size_t end) {
                constexpr size_t kAhead = 8;  // queries whose memory is fetched while this one runs
                for (size_t i = block + begin; i < block + end; ++i) {
                    // Fetched ahead for the sites to be queried, not for those a known centroid rejects.
                    if (i + 2 * kAhead < block + end && !(pending[i + 2 * kAhead].near2 < grid.radius2()))
                        __builtin_prefetch(&sites[pending[i + 2 * kAhead].triangle]);
                    if (i + kAhead < block + end && !(pending[i + kAhead].near2 < grid.radius2()))
                        grid.prefetch(sites[pending[i + kAhead].triangle]);
                    if (pending[i].near2 < grid.radius2()) {
                        near_ranked[i - block] = pending[i].near2;
                        continue;
                    }
                    near_ranked[i - block] = grid.nearest_within(sites[pending[i].triangle]);
                }
            });
            for (size_t i = block; i < block_end; ++i) {
                if (i + kArrivalAhead < block_end && !(near_ranked[i + kArrivalAhead - block] < INFINITY))
                    __builtin_prefetch(&sites[pending[i + kArrivalAhead].triangle]);
                const uint32_t t = pending[i].triangle;
                float near2 = near_ranked[i - block];
                if (near2 < INFINITY || (near2 = block_grid.nearest_within(sites[t])) < INFINITY) {
                    rejected.push_back({t, near2});
                } else {
                    ranked.push_back(t), ranked_sites.push_back(sites[t]);
                    block_grid.insert(sites[t]);
                }
            }
            for (size_t r = ranked.size() - block_grid.size(); r < ranked.size(); ++r) {
                if (r + kArrivalAhead < ranked_sites.size()) grid.prefetch(ranked_sites[r + kArrivalAhead]);
                grid.insert(ranked_sites[r]);
            }
            block_grid.clear();
        }
        // Unexamined sites go first at the next level, then the rejected ones.
        head += budget;
        if (head > pending.size() / 2) {
            pending.erase(pending.begin(), pending.begin() + std::ptrdiff_t(head));
            head = 0;
        }
        pending.insert(pending.end(), rejected.begin(), rejected.end());
    }
    std::vector<glm::vec3>().swap(ranked_sites);  // before the calibration's arrays
    for (size_t i = head; i < pending.size(); ++i) ranked.push_back(pending[i].triangle);
    ranked.insert(ranked.end(), weightless.begin(), weightless.end());

    // The ranking is about uniform over the surface's area, so a triangle a times the mean area reaches a
    // given rank about a times as often as the mean one: rank / count x relative area is close to uniform
    // for every triangle. Only close: a triangle far smaller than the mean has a value below its relative
    // area whatever its rank (it would be selected for certain once p passes that), and one far larger is
    // ranked before its regular share once its region runs out of sites. So the value is made exactly
    // uniform where it matters, among triangles of about the same area and count (calibrate_per_class).
    const double mean_area = area / double(count);
    std::vector<uint8_t> facings(count);
    for (size_t t = 0; t < count; ++t) {
        const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
        const glm::vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
        facings[t] = facing_bin(glm::cross(b - a, c - a));
    }
    std::vector<double> scaled(count);
    parallel_for_chunks(count, size_t(1) << 16, [&](size_t, size_t begin, size_t end) {  // each rank its own triangle
        for (size_t rank = begin; rank < end; ++rank) {
            if (rank + kFetchAhead < end) {
                __builtin_prefetch(&scaled[ranked[rank + kFetchAhead]], 1);
                __builtin_prefetch(&areas[ranked[rank + kFetchAhead]]);
            }
            const uint32_t t = ranked[rank];
            scaled[t] = double(rank) / double(count) * areas[t] / mean_area;
        }
    });
    // A triangle without weight never draws: its value is the last there is, and it takes no part in the
    // calibration (on a fine mesh at a low D_max most triangles have no candidate, and sorting them took
    // most of the calibration's time).
    std::vector<uint8_t> calibrated(count, 1);
    for (const uint32_t t : weightless) calibrated[t] = 0, values[t] = kLastValue;
    calibrate_per_class(areas, counts, facings, scaled, calibrated, seed, values);
    return values;
}

}  // namespace

std::vector<float> polygon_selection_values(const Mesh& mesh, uint64_t seed) {
    const size_t triangles = mesh.triangle_count();
    std::vector<glm::vec3> sites(triangles);
    for (size_t t = 0; t < triangles; ++t) sites[t] = centroid(mesh, t);
    return selection_values_at(mesh, std::move(sites), std::vector<uint32_t>(triangles, 0u), seed);
}

std::vector<float> polygon_selection_values(const Mesh& mesh, const StippleSet& stipples, uint64_t seed) {
    std::vector<glm::vec3> sites(mesh.triangle_count());
    std::vector<uint32_t> counts(sites.size(), 0u);
    const bool counted = stipples.first.size() == sites.size() + 1;
    for (size_t t = 0; t < sites.size(); ++t) {
        if (counted) counts[t] = stipples.count(t);
        sites[t] = counts[t] > 0 ? stipples.positions[stipples.first[t]] : centroid(mesh, t);
    }
    return selection_values_at(mesh, std::move(sites), counts, seed);
}

}  // namespace stipple
