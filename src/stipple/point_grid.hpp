#pragma once
// A static 3D spatial hash of points for fixed-radius neighbour queries (stipple relaxation, the
// progressive order, the nearest-neighbour quality metric; CellHash alone also serves the polygons'
// selection ranking).
//
// Points go into cubic cells; cells go into a power-of-two bucket table; a counting sort stores
// each bucket's points contiguously, as separate x, y, z arrays so that a query can stream
// through them with SIMD. Different cells may share a bucket: queries always test the real
// distance, so a collision costs a few extra distance tests and never a wrong answer.
//
// Bucket layout: space is tiled by windows of W^3 cells (W = 2^w), starting half a window below the
// points. Inside a window a cell's bucket is its row-major index (x fastest) plus a hash of the window,
// modulo the table. So neighbouring cells share cache lines, and the three cells x-1, x, x+1 of a row
// are three consecutive buckets (two runs where the row wraps around the table): the 27 neighbours of
// a cell are 9 contiguous runs of points.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/parallel.hpp"

namespace stipple {

// Cubic cells of a given size, numbered into a power-of-two table of buckets (see above).
class CellHash {
public:
    // About `buckets` buckets (rounded up to a power of two, at least 64).
    void init(const glm::vec3& origin, float cell_size, size_t buckets) {
        origin_ = origin;
        cell_size_ = cell_size;
        inv_cell_ = 1.0f / cell_size;
        int bits = 6;
        while (bits < 30 && (size_t(1) << bits) < buckets) ++bits;
        mask_ = (uint32_t(1) << bits) - 1;
        // Windows of at most 1/16 of the table: a surface meets only a 2D slice of a window, so
        // windows at random offsets rarely share buckets.
        window_bits_ = (bits - 4) / 3;
        // Half a window below the points: the faces of a box lie at their minimum, which would put
        // them on window borders, where every neighbourhood straddles two windows (the slow path of
        // PointGrid::neighbor_runs for half of a cube's stipples).
        if (window_bits_ > 0) origin_ -= glm::vec3(cell_size * float(1 << (window_bits_ - 1)));
    }

    glm::ivec3 cell_of(const glm::vec3& p) const {
        // Clamped so that far-away points stay representable; they merely share edge cells.
        const glm::vec3 lim(1.0e9f);
        const glm::vec3 c = glm::clamp((p - origin_) * inv_cell_, -lim, lim);
        // floor by truncation and correction: std::floor is a library call without SSE4.1.
        const glm::ivec3 i(c);
        return i - glm::ivec3(glm::lessThan(c, glm::vec3(i)));
    }

    uint32_t bucket(const glm::ivec3& c) const {
        const uint32_t wmask = (uint32_t(1) << window_bits_) - 1;
        const uint32_t local = (uint32_t(c.x) & wmask) | (uint32_t(c.y) & wmask) << window_bits_ |
                               (uint32_t(c.z) & wmask) << (2 * window_bits_);
        // The window's offset spans the whole table: a flat face meets each of its windows in the same
        // slice of local indices, and with offsets above the local bits alone (16 or so of them) the
        // windows sharing one piled their slices into the same buckets (a 12-triangle cube's relaxation
        // read twice its neighbours' points, its ordering pushed to them).
        return (local + window_hash(c)) & mask_;
    }

    // True when cells x0..x1 of a row (same y, z) are in one window.
    bool one_window(int x0, int x1) const { return (uint32_t(x0) >> window_bits_) == (uint32_t(x1) >> window_bits_); }
    bool one_window(const glm::ivec3& lo, const glm::ivec3& hi) const {
        return one_window(lo.x, hi.x) && one_window(lo.y, hi.y) && one_window(lo.z, hi.z);
    }
    // True when the cells x0..x1 of a row whose first cell has bucket `first_bucket` are in one window and
    // their buckets do not wrap around the table: then they are consecutive, first_bucket .. first_bucket +
    // (x1 - x0).
    bool row_is_run(uint32_t first_bucket, int x0, int x1) const {
        return one_window(x0, x1) && first_bucket + uint32_t(x1 - x0) <= mask_;
    }

    size_t bucket_count() const { return size_t(mask_) + 1; }
    float cell_size() const { return cell_size_; }
    // Within one window, the bucket of the cell one step along y (or z) is this many buckets on, modulo the
    // table: the window's cells share its hash, so a neighbourhood's rows need one hash, not nine.
    uint32_t y_step() const { return uint32_t(1) << window_bits_; }
    uint32_t z_step() const { return uint32_t(1) << (2 * window_bits_); }

private:
    uint32_t window_hash(const glm::ivec3& c) const {
        const uint32_t hx = uint32_t(c.x) >> window_bits_, hy = uint32_t(c.y) >> window_bits_,
                       hz = uint32_t(c.z) >> window_bits_;
        uint32_t h = hx * 0x9E3779B1u ^ hy * 0x85EBCA77u ^ hz * 0xC2B2AE3Du;
        h ^= h >> 15;
        h *= 0x2C1B3C6Du;
        h ^= h >> 12;
        return h;
    }

    glm::vec3 origin_{0.0f};
    float cell_size_ = 1.0f;
    float inv_cell_ = 1.0f;
    uint32_t mask_ = 63;
    int window_bits_ = 2;
};

class PointGrid {
public:
    struct Run {
        uint32_t begin, end;  // slots [begin, end)
    };

    // Rebuilds the grid for `points` with cubic cells of side `cell_size` (> 0). Deterministic:
    // within a bucket, points keep their input order.
    // `buckets_per_point`: 2 suits cells of a few points (see below); grids of large cells need
    // fewer.
    void build(std::span<const glm::vec3> points, float cell_size, double buckets_per_point = 2.0) {
        // Padded by one SIMD width of points that are out of every query's reach.
        const size_t n = points.size();
        const float far = std::numeric_limits<float>::max();
        // The x coordinates' storage holds the points' buckets while they are sorted, the y coordinates'
        // the sort's intermediate order (both are written only after): no scratch arrays beside the grid.
        xs_.resize(n + kPad), ys_.resize(n + kPad);
        sort_into_buckets(points, cell_size, buckets_per_point, xs_.data(), ys_.data());
        zs_.resize(n + kPad);
        parallel_for_chunks(n, kSortChunk, [&](size_t, size_t begin, size_t end) {
            for (size_t slot = begin; slot < end; ++slot) {
                const glm::vec3& p = points[index_[slot]];
                xs_[slot] = p.x, ys_[slot] = p.y, zs_[slot] = p.z;
            }
        });
        std::fill(xs_.begin() + n, xs_.end(), far), std::fill(ys_.begin() + n, ys_.end(), far);
        std::fill(zs_.begin() + n, zs_.end(), far);
    }

    // The grid's spatial order alone (the input index of every slot, as sorted_index gives it after
    // build with the same arguments), without the coordinates: 16 bytes a point at the peak, not 32,
    // or 20 `on_every_core`, which sorts on every core where that is worth it.
    static std::vector<uint32_t> spatial_order(std::span<const glm::vec3> points, float cell_size,
                                               double buckets_per_point = 2.0, bool on_every_core = false) {
        PointGrid grid;
        std::vector<float> scratch(points.size()), order(on_every_core ? points.size() : 0);
        grid.sort_into_buckets(points, cell_size, buckets_per_point, scratch.data(), on_every_core ? order.data() : nullptr);
        return std::move(grid.index_);
    }

    glm::ivec3 cell_of(const glm::vec3& p) const { return hash_.cell_of(p); }
    uint32_t bucket(const glm::ivec3& c) const { return hash_.bucket(c); }
    bool row_is_run(uint32_t first_bucket, int x0, int x1) const { return hash_.row_is_run(first_bucket, x0, x1); }

    // The points of the 27 cells around `cell` as runs of slots; returns the number of runs.
    // Runs never overlap (a bucket shared by two of the cells is listed once).
    int neighbor_runs(const glm::ivec3& cell, Run out[27]) const {
        int count = 0;
        if (hash_.one_window(cell - glm::ivec3(1), cell + glm::ivec3(1))) {
            // Distinct rows of one window, whose cells have distinct buckets: 9 disjoint runs of 3
            // consecutive buckets (a row that wraps around the table, rarely, in two runs).
            for (int z = -1; z <= 1; ++z)
                for (int y = -1; y <= 1; ++y) {
                    const uint32_t first = bucket(cell + glm::ivec3(-1, y, z));
                    if (first + 3 <= bucket_count()) {
                        out[count++] = {start(first), start(first + 3)};
                        continue;
                    }
                    const uint32_t last = first + 2 - uint32_t(bucket_count());  // wrapped to the start
                    out[count++] = {start(first), start(uint32_t(bucket_count()))};
                    out[count++] = {start(0), start(last + 1)};
                }
            return count;
        }
        uint32_t buckets[27];
        for (int z = -1; z <= 1; ++z)
            for (int y = -1; y <= 1; ++y)
                for (int x = -1; x <= 1; ++x) buckets[count++] = bucket(cell + glm::ivec3(x, y, z));
        std::sort(buckets, buckets + count);
        count = static_cast<int>(std::unique(buckets, buckets + count) - buckets);
        for (int i = 0; i < count; ++i) out[i] = {start(buckets[i]), start(buckets[i] + 1)};
        return count;
    }

    // The distinct buckets of the cells in [lo, hi] (inclusive), sorted ascending.
    void buckets_in_box(const glm::ivec3& lo, const glm::ivec3& hi, std::vector<uint32_t>& out) const {
        out.clear();
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) out.push_back(bucket({x, y, z}));
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    size_t bucket_count() const { return hash_.bucket_count(); }
    size_t sorted_size() const { return index_.size(); }  // the points built from
    uint32_t bucket_begin(uint32_t b) const { return start(b); }
    uint32_t bucket_end(uint32_t b) const { return start(b + 1); }
    glm::vec3 sorted_position(uint32_t slot) const { return {xs_[slot], ys_[slot], zs_[slot]}; }
    uint32_t sorted_index(uint32_t slot) const { return index_[slot]; }  // input index of a slot
    // Frees the input indices (sorted_index and sorted_size are then unusable): 4 bytes a point, for a
    // caller that names its points by slot.
    void release_index() { std::vector<uint32_t>().swap(index_); }
    // Coordinates by slot, readable up to kPad slots past the last point.
    const float* xs() const { return xs_.data(); }
    const float* ys() const { return ys_.data(); }
    const float* zs() const { return zs_.data(); }
    float cell_size() const { return hash_.cell_size(); }

    static constexpr size_t kPad = 8;

private:
    // hash_, the bucket starts and index_ for `points`. Deterministic: within a bucket, points keep
    // their input order (a stable sort has one result, however it is computed). `scratch` (n floats)
    // holds each point's bucket as a word meanwhile; `order` (n floats, or null: one core) the order by
    // block of buckets (sort_in_blocks). Computing the buckets again where needed instead of holding
    // them took longer than sorting on one core: the input is in triangle order, not spatial.
    void sort_into_buckets(std::span<const glm::vec3> points, float cell_size, double buckets_per_point,
                           float* scratch, float* order) {
        const size_t n = points.size();
        glm::vec3 lo(0.0f);
        if (n > 0) {
            std::vector<glm::vec3> lows((n + kSortChunk - 1) / kSortChunk, points[0]);
            parallel_for_chunks(n, kSortChunk, [&](size_t chunk, size_t begin, size_t end) {
                for (size_t i = begin; i < end; ++i) lows[chunk] = glm::min(lows[chunk], points[i]);
            });
            lo = points[0];
            for (const glm::vec3& low : lows) lo = glm::min(lo, low);
        }
        // Two buckets per point by default. Cells hold several points, so most buckets are empty,
        // but a collision costs more than an empty bucket: a query reads the other cell's points too, and
        // the relaxation gathers a cell's neighbourhood again whenever the cell changes within a
        // bucket. (n / 2 buckets made generation 1.3-2x slower.)
        hash_.init(lo, cell_size, static_cast<size_t>(buckets_per_point * double(n)));
        parallel_for(n, 65536, [&](size_t i) { put(scratch, i, hash_.bucket(hash_.cell_of(points[i]))); });
        index_.resize(n);
        if (order != nullptr && n >= 2 * kSortChunk && sort_in_blocks(n, scratch, order))
            return;
        sort_serially(n, scratch);
    }

    // A word (a bucket or a point's index) in float storage, copied rather than aliased.
    static void put(float* words, size_t i, uint32_t word) { std::memcpy(words + i, &word, sizeof word); }
    static uint32_t get(const float* words, size_t i) {
        uint32_t word;
        std::memcpy(&word, words + i, sizeof word);
        return word;
    }

    // The counting sort on two cores (the 8M-stipple dragon's relaxation grids took 0.13 s each with
    // its counting and scattering on one core, 0.10 now): points are sorted by block of buckets first,
    // each chunk of them counted and scattered on its own (a chunk's points land after the earlier
    // chunks' in every block), then every block by bucket on its own (its 256 buckets' counts and its
    // points stay in the caches). False when a block holds more than 16-bit offsets can count: the
    // caller then sorts on one core, which sets every start again.
    bool sort_in_blocks(size_t n, const float* scratch, float* order) {
        auto bucket_of = [scratch](size_t i) { return get(scratch, i); };
        const size_t buckets = hash_.bucket_count();
        if (buckets < (size_t(1) << kBlockShift)) return false;
        const size_t blocks = buckets >> kBlockShift;
        // At most 8 chunks, so that the counts stay small: where the chunks end changes nothing in the result.
        const size_t chunk = std::max(kSortChunk, (n + 7) / 8);
        const size_t chunks = (n + chunk - 1) / chunk;
        // cursor[c * blocks + b]: chunk c's count in block b, then where its next point in block b goes.
        std::vector<uint32_t> cursor(chunks * blocks, 0);
        parallel_for_chunks(n, chunk, [&](size_t c, size_t begin, size_t end) {
            uint32_t* count = cursor.data() + c * blocks;
            for (size_t i = begin; i < end; ++i) ++count[bucket_of(i) >> kBlockShift];
        });
        block_start_.assign(blocks + 1, 0);
        uint32_t total = 0;
        for (size_t b = 0; b < blocks; ++b) {
            block_start_[b] = total;
            uint32_t in_block = 0;
            for (size_t c = 0; c < chunks; ++c) {
                const uint32_t count = cursor[c * blocks + b];
                cursor[c * blocks + b] = total + in_block;
                in_block += count;
            }
            if (in_block > UINT16_MAX) return false;
            total += in_block;
        }
        block_start_[blocks] = total;
        block_shift_ = kBlockShift;
        parallel_for_chunks(n, chunk, [&](size_t c, size_t begin, size_t end) {
            uint32_t* next = cursor.data() + c * blocks;
            for (size_t i = begin; i < end; ++i) put(order, next[bucket_of(i) >> kBlockShift]++, static_cast<uint32_t>(i));
        });
        offset_.assign(buckets + 1, 0);
        constexpr uint32_t kInBlock = (uint32_t(1) << kBlockShift) - 1;
        parallel_for_chunks(blocks, 64, [&](size_t, size_t first, size_t last) {
            for (size_t block = first; block < last; ++block) {
                const uint32_t begin = block_start_[block], end = block_start_[block + 1];
                uint16_t* offset = offset_.data() + (block << kBlockShift);
                for (uint32_t j = begin; j < end; ++j) ++offset[bucket_of(get(order, j)) & kInBlock];
                uint16_t running = 0;
                for (uint32_t b = 0; b <= kInBlock; ++b) {
                    const uint16_t count = offset[b];
                    offset[b] = running;
                    running = static_cast<uint16_t>(running + count);
                }
                // Bucket b's start as its cursor leaves it at bucket b + 1's start; one shift puts them back.
                for (uint32_t j = begin; j < end; ++j) {
                    const uint32_t i = get(order, j);
                    index_[begin + offset[bucket_of(i) & kInBlock]++] = i;
                }
                for (uint32_t b = kInBlock; b > 0; --b) offset[b] = offset[b - 1];
                offset[0] = 0;
            }
        });
        return true;
    }

    void sort_serially(size_t n, const float* scratch) {
        auto get = [scratch](size_t i) { return PointGrid::get(scratch, i); };
        // Bucket b starts at block_start_[b >> block_shift_] + offset_[b] (see start). Blocks hold at
        // most 65535 points, unless a pile of points fills one (many faces overlapping in one place) or
        // the table is smaller than a block: then every bucket is a block of its own (offsets all 0).
        const size_t buckets = hash_.bucket_count();
        block_shift_ = 0;
        if (buckets >= (size_t(1) << kBlockShift)) {  // a power of two: whole blocks
            std::vector<uint32_t> per_block(buckets >> kBlockShift, 0);
            for (size_t i = 0; i < n; ++i) ++per_block[get(i) >> kBlockShift];
            if (*std::max_element(per_block.begin(), per_block.end()) <= UINT16_MAX) block_shift_ = kBlockShift;
        }
        block_start_.assign((buckets >> block_shift_) + 1, 0);
        offset_.assign(buckets + 1, 0);
        // Counts: a bucket's in its block's table while the block's fit 16 bits, else in the block start.
        if (block_shift_ == 0) {
            for (size_t i = 0; i < n; ++i) ++block_start_[get(i) + 1];
            for (size_t b = 1; b < block_start_.size(); ++b) block_start_[b] += block_start_[b - 1];
        } else {
            for (size_t i = 0; i < n; ++i) ++offset_[get(i)];
            // Within each block, counts to starts relative to the block; the blocks' starts add up.
            uint32_t total = 0;
            for (size_t block = 0; block + 1 < block_start_.size(); ++block) {
                block_start_[block] = total;
                uint32_t running = 0;
                const size_t first = block << block_shift_;
                const size_t last = std::min(buckets, first + (size_t(1) << block_shift_));
                for (size_t b = first; b < last; ++b) {
                    const uint32_t count = offset_[b];
                    offset_[b] = static_cast<uint16_t>(running);
                    running += count;
                }
                total += running;
            }
            block_start_.back() = total;  // the end sentinel's block (offset_[buckets] is 0)
        }
        // Scatter with bucket b's start as its cursor, which leaves it at bucket b's end (the next
        // bucket's start); one shift puts the starts back. No cursor array of bucket-table size.
        if (block_shift_ == 0) {
            for (size_t i = 0; i < n; ++i) index_[block_start_[get(i)]++] = static_cast<uint32_t>(i);
            for (size_t b = block_start_.size() - 1; b > 0; --b) block_start_[b] = block_start_[b - 1];
            block_start_[0] = 0;
        } else {
            for (size_t i = 0; i < n; ++i) {
                const uint32_t b = get(i);
                index_[block_start_[b >> block_shift_] + offset_[b]++] = static_cast<uint32_t>(i);
            }
            const size_t block_size = size_t(1) << block_shift_;
            for (size_t b = buckets - 1; b > 0; --b) offset_[b] = (b & (block_size - 1)) == 0 ? 0 : offset_[b - 1];
            offset_[0] = 0;
        }
    }

    // Where bucket b's points start (b up to bucket_count(), whose start is the end of the points).
    uint32_t start(uint32_t b) const { return block_start_[b >> block_shift_] + offset_[b]; }

    // 256 buckets share a 32-bit start: 2.02 bytes a bucket instead of 4. At the relaxation's two
    // buckets a point (rounded up to a power of two) 32-bit starts were 8-16 of the 40 bytes a stipple
    // cost there (issue 17 asks at most 40 bytes a generated stipple, the whole program included).
    static constexpr int kBlockShift = 8;
    // Points per chunk of the parallel passes over them.
    static constexpr size_t kSortChunk = size_t(1) << 18;
    std::vector<uint32_t> block_start_;  // by block of 2^block_shift_ buckets
    std::vector<uint16_t> offset_;       // by bucket: its start within its block
    int block_shift_ = 0;
    CellHash hash_;
    std::vector<float> xs_, ys_, zs_;
    std::vector<uint32_t> index_;
};

}  // namespace stipple
