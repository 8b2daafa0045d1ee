#include "export/tour_improve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace stipple::plot {

namespace {

// Moves must gain at least this (mm), so rounding can never make two moves undo each other forever.
constexpr double kMinGain = 1e-7;
constexpr uint32_t kMaxSegment = 3;  // Or-opt moves runs of 1 to 3 dots

class PathImprover {
public:
    PathImprover(std::span<const glm::dvec2> points, const NeighbourLists& neighbours, const std::vector<uint32_t>& order)
        : points_(points), neighbours_(neighbours), virtual_(static_cast<uint32_t>(points.size())), m_(static_cast<uint32_t>(points.size()) + 1) {
        tour_ = order;
        tour_.push_back(virtual_);
        pos_.resize(m_);
        for (uint32_t p = 0; p < m_; ++p) pos_[tour_[p]] = p;
    }

    ImproveCounts run() {
        // Every dot starts queued, in path order; a dot is queued again when an edge at it changed.
        std::deque<uint32_t> queue(tour_.begin(), tour_.end() - 1);
        queued_.assign(m_, 1);
        queued_[virtual_] = 0;
        while (!queue.empty()) {
            const uint32_t t = queue.front();
            queue.pop_front();
            queued_[t] = 0;
            while (try_two_opt(t) || try_or_opt(t)) {
            }
            for (const uint32_t v : touched_)
                if (v != virtual_ && v != t && !queued_[v]) queued_[v] = 1, queue.push_back(v);  // t has no move left
            touched_.clear();
        }
        return counts_;
    }

    // The improved path: the tour cut at the virtual point.
    std::vector<uint32_t> path() const {
        std::vector<uint32_t> order;
        order.reserve(m_ - 1);
        for (uint32_t k = 1; k < m_; ++k) order.push_back(tour_[(pos_[virtual_] + k) % m_]);
        return order;
    }

private:
    double dist(uint32_t a, uint32_t b) const {
        if (a == virtual_ || b == virtual_) return 0.0;
        const glm::dvec2 d = points_[a] - points_[b];
        return std::sqrt(d.x * d.x + d.y * d.y);
    }
    uint32_t wrap(int64_t p) const { return static_cast<uint32_t>(((p % m_) + m_) % m_); }
    uint32_t at(int64_t p) const { return tour_[wrap(p)]; }
    uint32_t succ(uint32_t v) const { return tour_[pos_[v] + 1 == m_ ? 0 : pos_[v] + 1]; }
    uint32_t pred(uint32_t v) const { return tour_[pos_[v] == 0 ? m_ - 1 : pos_[v] - 1]; }
    void place(int64_t p, uint32_t v) {
        const uint32_t w = p >= 0 && p < m_ ? static_cast<uint32_t>(p) : wrap(p);
        tour_[w] = v;
        pos_[v] = w;
    }
    std::span<const uint32_t> candidates(uint32_t v) const {
        return v == virtual_ ? std::span<const uint32_t>() : neighbours_.of(v);
    }

    // Reverses the tour from position i forward to position j (inclusive), or the rest of the tour
    // when that is shorter: both give the same cyclic tour, mirrored.
    void reverse(uint32_t i, uint32_t j) {
        uint32_t len = (j + m_ - i) % m_ + 1;
        if (2 * len > m_) {
            const uint32_t new_i = (j + 1) % m_;
            j = (i + m_ - 1) % m_;
            i = new_i;
            len = m_ - len;
        }
        // Two cursors walking towards each other, wrapping by comparison (a modulo per step costs more
        // than the swap itself on long reversals).
        uint32_t a = i, b = j;
        for (uint32_t k = 0; k < len / 2; ++k) {
            const uint32_t va = tour_[a], vb = tour_[b];
            tour_[a] = vb;
            pos_[vb] = a;
            tour_[b] = va;
            pos_[va] = b;
            a = a + 1 == m_ ? 0 : a + 1;
            b = b == 0 ? m_ - 1 : b - 1;
        }
    }

    // Replaces edges (t1,t2),(t3,t4) by (t1,t3),(t2,t4), with t2 and t4 both successors or both
    // predecessors; t3 from t1's neighbours (and the virtual point, which frees a path end).
    bool try_two_opt(uint32_t t1) {
        for (const bool forward : {true, false}) {
            const uint32_t t2 = forward ? succ(t1) : pred(t1);
            const double d12 = dist(t1, t2);
            const std::span<const uint32_t> near = candidates(t1);
            for (size_t c = 0; c <= near.size(); ++c) {
                const uint32_t t3 = c < near.size() ? near[c] : virtual_;
                const double g1 = d12 - dist(t1, t3);
                if (g1 <= kMinGain) {
                    if (c < near.size()) c = near.size() - 1;  // the list is sorted: only the virtual point is left
                    continue;
                }
                const uint32_t t4 = forward ? succ(t3) : pred(t3);
                if (t3 == t2 || t4 == t1 || t3 == t1) continue;
                if (g1 + dist(t3, t4) - dist(t2, t4) <= kMinGain) continue;
                if (forward) reverse(pos_[t2], pos_[t3]);
                else reverse(pos_[t1], pos_[t4]);
                touched_.insert(touched_.end(), {t1, t2, t3, t4});
                ++counts_.two_opt_moves;
                return true;
            }
        }
        return false;
    }

    // Moves a run of 1-3 dots that starts or ends at t to between two neighbours elsewhere, either
    // way round.
    bool try_or_opt(uint32_t t) {
        if (m_ < 2 * kMaxSegment + 2) return false;
        for (uint32_t len = 1; len <= kMaxSegment; ++len)
            for (const bool starts_at_t : {true, false}) {
                if (len == 1 && !starts_at_t) continue;
                const int64_t start = starts_at_t ? int64_t(pos_[t]) : int64_t(pos_[t]) - (len - 1);
                if (try_move_run(start, len)) return true;
            }
        return false;
    }

    bool try_move_run(int64_t start, uint32_t len) {
        const uint32_t first = at(start), last = at(start + len - 1);
        const uint32_t before = at(start - 1), after = at(start + len);
        const double removed = dist(before, first) + dist(last, after) - dist(before, after);
        if (removed <= kMinGain) return false;
        const uint32_t s = wrap(start);
        const auto in_run = [&](uint32_t v) { return (pos_[v] + m_ - s) % m_ < len; };

        for (const uint32_t end : {first, last})
            for (const uint32_t c : candidates(end)) {
                if (removed - dist(end, c) <= kMinGain) break;  // sorted: no nearer candidate is left
                if (in_run(c)) continue;
                for (const bool c_first : {true, false}) {
                    const uint32_t u = c_first ? c : pred(c), v = c_first ? succ(c) : c;
                    if (in_run(u) || in_run(v)) continue;
                    const double plain = dist(u, first) + dist(last, v), flipped = dist(u, last) + dist(first, v);
                    const double added = std::min(plain, flipped) - dist(u, v);
                    if (removed - added <= kMinGain) continue;
                    move_run(s, len, u, flipped < plain);
                    touched_.insert(touched_.end(), {first, last, before, after, u, v});
                    ++counts_.or_opt_moves;
                    return true;
                }
            }
        return false;
    }

    // Moves the run at positions s..s+len-1 to just after u, shifting whichever arc is shorter.
    void move_run(uint32_t s, uint32_t len, uint32_t u, bool flip) {
        std::array<uint32_t, kMaxSegment> run{};
        for (uint32_t k = 0; k < len; ++k) run[k] = tour_[(s + k) % m_];
        if (flip) std::reverse(run.begin(), run.begin() + len);
        const uint32_t q = pos_[u];
        const uint32_t after_run = (q + m_ - (s + len - 1) % m_) % m_;  // dots from the run's successor to u
        const uint32_t before_run = m_ - len - after_run;                 // dots from u's successor to the run's predecessor
        if (after_run <= before_run) {
            uint32_t to = s, from = (s + len) % m_;
            for (uint32_t k = 0; k < after_run; ++k) {
                place(to, tour_[from]);
                to = to + 1 == m_ ? 0 : to + 1;
                from = from + 1 == m_ ? 0 : from + 1;
            }
            for (uint32_t k = 0; k < len; ++k) place(int64_t(s) + after_run + k, run[k]);
        } else {
            uint32_t to = (q + len + before_run) % m_, from = (q + before_run) % m_;
            for (uint32_t k = 0; k < before_run; ++k) {
                place(to, tour_[from]);
                to = to == 0 ? m_ - 1 : to - 1;
                from = from == 0 ? m_ - 1 : from - 1;
            }
            for (uint32_t k = 0; k < len; ++k) place(int64_t(q) + 1 + k, run[k]);
        }
    }

    std::span<const glm::dvec2> points_;
    const NeighbourLists& neighbours_;
    const uint32_t virtual_;  // the point at distance 0 from all, where the tour is cut into a path
    const uint32_t m_;        // tour length: the dots and the virtual point
    std::vector<uint32_t> tour_, pos_;
    std::vector<uint8_t> queued_;
    std::vector<uint32_t> touched_;
    ImproveCounts counts_;
};

}  // namespace

ImproveCounts improve_path(std::span<const glm::dvec2> points, const NeighbourLists& neighbours, std::vector<uint32_t>& order) {
    if (order.size() < 4) return {};
    PathImprover improver(points, neighbours, order);
    const ImproveCounts counts = improver.run();
    order = improver.path();
    return counts;
}

}  // namespace stipple::plot
