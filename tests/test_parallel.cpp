// core/parallel.hpp: every chunk runs once whatever the threads, the pool of workers serves call after
// call, and calls that find it taken (from another thread, or from inside a chunk) still complete.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.hpp"

namespace stipple {
namespace {

// Runs parallel_for_chunks over n items and returns how many times each chunk ran.
std::vector<int> runs_per_chunk(size_t n, size_t chunk) {
    std::vector<std::atomic<int>> runs((n + chunk - 1) / chunk);
    parallel_for_chunks(n, chunk, [&](size_t c, size_t begin, size_t end) {
        EXPECT_EQ(begin, c * chunk);
        EXPECT_EQ(end, std::min(n, (c + 1) * chunk));
        runs[c].fetch_add(1);
    });
    std::vector<int> out;
    for (const auto& r : runs) out.push_back(r.load());
    return out;
}

TEST(Parallel, EveryChunkRunsOnceForAnyThreadCount) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        set_worker_count(threads);
        for (size_t n : {1u, 7u, 1000u, 100003u}) {
            const std::vector<int> runs = runs_per_chunk(n, 64);
            for (size_t c = 0; c < runs.size(); ++c) ASSERT_EQ(runs[c], 1) << "chunk " << c << " of " << n << ", " << threads << " threads";
        }
    }
    set_worker_count(0);
}

TEST(Parallel, ThePoolServesManyCallsInARow) {
    // A lost wake-up or a worker left behind would hang or lose chunks within a few thousand jobs; and
    // the same few threads run them all (threads started per call would be thousands).
    set_worker_count(4);
    long total = 0;
    std::atomic<int> threads_seen{0};  // each thread counts itself once (thread ids are reused, this is not)
    for (int call = 0; call < 5000; ++call) {
        std::atomic<long> sum{0};
        parallel_for(16, 1, [&](size_t i) {
            sum += long(i);
            thread_local bool counted = false;
            if (!counted) counted = true, ++threads_seen;
        });
        total += sum.load();
    }
    EXPECT_EQ(total, 5000L * 120);
    std::printf("5000 calls on 4 threads ran on %d threads\n", threads_seen.load());
    EXPECT_LE(threads_seen.load(), 4);
    set_worker_count(0);
}

TEST(Parallel, CallsInsideAChunkAndFromOtherThreadsComplete) {
    set_worker_count(2);
    // Nested: each outer chunk runs a whole inner loop.
    std::atomic<long> inner{0};
    parallel_for(8, 1, [&](size_t) { parallel_for(100, 10, [&](size_t i) { inner += long(i); }); });
    EXPECT_EQ(inner.load(), 8L * 4950);
    // Two threads calling at once: one has the pool, the other threads of its own, both finish.
    std::atomic<long> sums[2] = {0, 0};
    std::vector<std::thread> callers;
    for (int k = 0; k < 2; ++k)
        callers.emplace_back([&, k] {
            for (int call = 0; call < 300; ++call) parallel_for(64, 4, [&](size_t i) { sums[k] += long(i); });
        });
    for (std::thread& t : callers) t.join();
    EXPECT_EQ(sums[0].load(), 300L * 2016);
    EXPECT_EQ(sums[1].load(), 300L * 2016);
    set_worker_count(0);
}

TEST(Parallel, TheFirstExceptionOfABodyReachesTheCaller) {
    set_worker_count(2);
    EXPECT_THROW(parallel_for(1000, 1, [](size_t i) {
                     if (i == 500) throw std::runtime_error("chunk 500");
                 }),
                 std::runtime_error);
    // And the pool still works after it.
    std::atomic<int> count{0};
    parallel_for(1000, 1, [&](size_t) { ++count; });
    EXPECT_EQ(count.load(), 1000);
    set_worker_count(0);
}

}  // namespace
}  // namespace stipple
