#include "app/background_work.hpp"

#include <filesystem>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

#include "core/error.hpp"

namespace stipple::app {

BackgroundWork::BackgroundWork(const gpu::Context& context) : context_(context), worker_([this] { run(); }) {}

BackgroundWork::~BackgroundWork() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        queue_.clear();
        if (observer_) observer_->cancel();
    }
    wake_.notify_all();
    worker_.join();
}

void BackgroundWork::regenerate(uint64_t object_id, const ObjectData& model, const ObjectParams& params) {
    ObjectData shape = model;
    shape.stipples.reset();  // the old set is not needed by the worker
    std::lock_guard<std::mutex> lock(mutex_);
    auto same_object = [&](const Job& job) {
        return job.kind == FinishedWork::Kind::Regenerated && job.object_id == object_id;
    };
    // The newest value wins: older requests for this object are dropped, a running one is cancelled.
    queue_.erase(std::remove_if(queue_.begin(), queue_.end(), same_object), queue_.end());
    if (running_ && same_object(*running_) && observer_) observer_->cancel();
    // Named by its file: the id is internal (it starts at 1 and outlives removals), not the panel's number.
    const std::string name = shape.mesh && !shape.mesh->source.empty()
                                 ? std::filesystem::path(shape.mesh->source).filename().string()
                                 : "object";
    queue_.push_back({FinishedWork::Kind::Regenerated, object_id, "", std::move(shape), params, "new stipples for " + name});
    wake_.notify_one();
}

void BackgroundWork::load(const std::string& path, const ObjectParams& params, uint64_t planned_before) {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back({FinishedWork::Kind::Loaded, 0, path, ObjectData{}, params, "loading " + path, planned_before});
    wake_.notify_one();
}

std::vector<FinishedWork> BackgroundWork::take_finished() {
    std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(finished_, {});
}

std::optional<BackgroundWork::Status> BackgroundWork::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!running_) return std::nullopt;
    return Status{running_->label, observer_ ? observer_->fraction() : 0.0, queue_.size()};
}

bool BackgroundWork::idle() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return !running_ && queue_.empty() && finished_.empty();
}

void BackgroundWork::run() {
    // Below the UI thread: on a CPU renderer (lavapipe) generation and drawing share the cores, and the
    // frames must keep coming. A Linux thread's nice value is its own and passes to the threads it
    // starts (the generation's parallel loops).
    setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), 10);
    for (;;) {
        Job job;
        std::shared_ptr<ProgressObserver> observer = std::make_shared<ProgressObserver>();
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
            if (stopping_) return;
            job = std::move(queue_.front());
            queue_.pop_front();
            running_ = job;
            observer_ = observer;
        }
        std::optional<FinishedWork> result;
        try {
            ScopedProgressObserver watch(observer.get());
            result = execute(job);
        } catch (const Cancelled&) {
            // A newer request replaced it: nothing to hand back.
        } catch (const Error& e) {
            result.emplace();
            result->kind = FinishedWork::Kind::Failed;
            result->path = job.path;
            result->error = e.what();
        } catch (const std::bad_alloc&) {
            result.emplace();
            result->kind = FinishedWork::Kind::Failed;
            result->path = job.path;
            result->error = "out of memory while " + job.label;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (result && !observer->cancelled()) finished_.push_back(std::move(*result));
        running_.reset();
        observer_.reset();
    }
}

FinishedWork BackgroundWork::execute(const Job& job) {
    FinishedWork work;
    work.kind = job.kind;
    work.object_id = job.object_id;
    work.path = job.path;
    work.params = job.params;
    work.data = job.kind == FinishedWork::Kind::Loaded ? load_model_data(job.path) : job.model;
    // A count this device cannot hold is refused before the stipples are made (minutes at a high D_max).
    check_model_fits(context_, work.data, job.params.generation, job.planned_before);
    // Named by its file in what it refuses (the host's memory, memory that runs out).
    const std::string& path = job.path.empty() && work.data.mesh ? work.data.mesh->source : job.path;
    work.data.stipples = make_model_stipples(path, work.data, job.params.generation);
    work.upload = std::make_unique<ObjectUpload>(
        prepare_object_upload(context_, *work.data.mesh, *work.data.stipples, job.params.generation.seed,
                              work.data.motion));
    return work;
}

}  // namespace stipple::app
