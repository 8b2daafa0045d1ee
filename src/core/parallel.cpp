#include "core/parallel.hpp"

#include <condition_variable>
#include <cstdint>

namespace stipple::detail {

namespace {

// Set on a thread while it runs a job of the pool (the caller's thread included): a parallel_for_chunks
// inside a chunk then starts threads of its own instead of waiting for the pool it is part of.
thread_local bool running_pool_job = false;

// Workers started on first use and kept until the program ends, each waiting for the next job. One job at
// a time: whoever holds `taken_` has the pool; others fall back to threads of their own.
class WorkerPool {
public:
    bool run(const PoolJob& job, unsigned threads) {
        if (running_pool_job || threads < 2) return false;
        std::unique_lock<std::mutex> taken(taken_, std::try_to_lock);
        if (!taken.owns_lock()) return false;
        unsigned helpers = threads - 1;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            while (workers_.size() < helpers) {
                const unsigned index = static_cast<unsigned>(workers_.size());
                try {
                    workers_.emplace_back([this, index] { work(index); });
                } catch (const std::exception&) {  // std::system_error, or std::bad_alloc for the thread's state
                    // No thread to be had (a limit on processes, or memory): the job runs on those there are,
                    // the caller's alone at worst. Its chunks are taken as they come, so the result is the same.
                    helpers = static_cast<unsigned>(workers_.size());
                    break;
                }
            }
            job_ = job;
            helpers_ = helpers;
            finished_ = 0;
            ++generation_;
        }
        wake_.notify_all();
        running_pool_job = true;
        job.run(job.context, 0);
        running_pool_job = false;
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return finished_ == helpers_; });
        return true;
    }

private:
    void work(unsigned index) {
        running_pool_job = true;
        uint64_t seen = 0;
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return generation_ != seen; });
            seen = generation_;
            if (index >= helpers_) continue;  // a job that needs fewer threads than the pool has
            const PoolJob job = job_;
            lock.unlock();
            job.run(job.context, index + 1);
            lock.lock();
            if (++finished_ == helpers_) done_.notify_one();
        }
    }

    std::mutex taken_;  // held by the thread whose job the pool runs
    std::mutex mutex_;  // the fields below
    std::condition_variable wake_, done_;
    std::vector<std::thread> workers_;
    PoolJob job_{};
    unsigned helpers_ = 0, finished_ = 0;
    uint64_t generation_ = 0;  // one more per job
};

}  // namespace

bool run_on_pool(const PoolJob& job, unsigned threads) {
    // Never destroyed: its workers wait for jobs until the program exits (a destructor would have to
    // stop and join them after main, when another static's destructor may still run a loop).
    static WorkerPool* const pool = new WorkerPool();
    return pool->run(job, threads);
}

}  // namespace stipple::detail
