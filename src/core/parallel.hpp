#pragma once
// A tiny deterministic parallel_for over a pool of std::threads.
//
// Work is cut into fixed chunks whose boundaries depend only on the problem size and the chunk
// size the caller gives, never on the number of threads; threads take chunks in any order. So a
// body that writes only the outputs of its own chunk (and combines per-chunk results in chunk
// order afterwards) gives bit-identical results for any thread count, including 1.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"

namespace stipple {

namespace detail {
inline std::atomic<unsigned>& worker_override() {
    static std::atomic<unsigned> value{0};
    return value;
}
}  // namespace detail

// Number of worker threads used by parallel_for: set_worker_count's value if set, else the value
// of the STIPPLE_THREADS environment variable, else the hardware concurrency. (1 forces serial
// execution; handy to check that results do not depend on the thread count.)
inline unsigned worker_count() {
    if (const unsigned forced = detail::worker_override().load(std::memory_order_relaxed)) return forced;
    static const unsigned count = [] {
        if (const char* env = std::getenv("STIPPLE_THREADS"); env && *env) {
            char* end = nullptr;
            const long n = std::strtol(env, &end, 10);
            // Until 2026-12-04 "abc" or "-3" silently meant the hardware's count.
            if (end == env || *end != '\0' || n < 1 || n > 1024)
                fail(std::string("STIPPLE_THREADS=") + env + " is not a thread count from 1 to 1024");
            return static_cast<unsigned>(n);
        }
        const unsigned hw = std::thread::hardware_concurrency();
        return hw == 0 ? 1u : hw;
    }();
    return count;
}

// Overrides worker_count() (0 restores the default). For tests and benchmarks.
inline void set_worker_count(unsigned threads) { detail::worker_override().store(threads, std::memory_order_relaxed); }

namespace detail {
// What each thread of a job runs: run(context, k) on thread k of the job (0: the caller). It must not throw.
struct PoolJob {
    void (*run)(void* context, unsigned thread);
    void* context;
};
// Runs `job` once on each of `threads` threads, the calling one among them, with the program's pool of
// workers (parallel.cpp), and returns when all have finished. False, having run nothing, when the pool is
// taken: by another thread's job, or (called from inside a job) by the job this thread is running.
bool run_on_pool(const PoolJob& job, unsigned threads);
}  // namespace detail

// Calls body(chunk_index, begin, end) for every chunk [begin, end) of [0, n) of `chunk` items
// (the last one shorter). Blocks until all chunks ran. The first exception thrown by a body is
// rethrown here (the remaining chunks are skipped).
//
// The chunks run on a pool of workers started once: starting a thread a call took 58 us on this 2-core
// machine when quiet, 108 under load, and generating the horse's or the fox's stipples makes 200-250
// calls (docs/performance.md, "A pool of workers"). A call made while the pool is taken (another
// thread's, or one inside a chunk) starts threads of its own.
template <class Body>
void parallel_for_chunks(size_t n, size_t chunk, Body&& body) {
    if (n == 0) return;
    chunk = std::max<size_t>(chunk, 1);
    const size_t chunks = (n + chunk - 1) / chunk;
    const unsigned threads = static_cast<unsigned>(std::min<size_t>(worker_count(), chunks));
    if (threads <= 1) {
        for (size_t c = 0; c < chunks; ++c) body(c, c * chunk, std::min(n, (c + 1) * chunk));
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        for (;;) {
            const size_t c = next.fetch_add(1, std::memory_order_relaxed);
            if (c >= chunks) return;
            try {
                body(c, c * chunk, std::min(n, (c + 1) * chunk));
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                next.store(chunks, std::memory_order_relaxed);  // skip the rest
            }
        }
    };
    // Every thread of the job runs `worker`, which takes chunks until none is left (and throws nothing).
    const detail::PoolJob job{[](void* context, unsigned) { (*static_cast<decltype(worker)*>(context))(); }, &worker};
    if (detail::run_on_pool(job, threads)) {
        if (error) std::rethrow_exception(error);
        return;
    }
    std::vector<std::thread> own_threads;  // the pool is taken: threads of this call's own
    own_threads.reserve(threads - 1);
    try {
        for (unsigned i = 1; i < threads; ++i) own_threads.emplace_back(worker);
    } catch (const std::exception&) {  // std::system_error, or std::bad_alloc for the thread's state
        // No more threads to be had (a limit on processes, or memory): those started and this one take every chunk.
    }
    worker();  // the calling thread works too
    for (std::thread& t : own_threads) t.join();
    if (error) std::rethrow_exception(error);
}

// Calls body(i) for every i in [0, n), in chunks of `chunk` consecutive indices.
template <class Body>
void parallel_for(size_t n, size_t chunk, Body&& body) {
    parallel_for_chunks(n, chunk, [&](size_t, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) body(i);
    });
}

}  // namespace stipple
