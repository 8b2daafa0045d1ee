#pragma once
// The viewer's slow work off the UI thread: new stipples after a generation parameter changed, and models
// dropped onto the window. One worker thread runs one job at a time; a newer request for the same object
// cancels the running one (at its next progress report) and replaces any queued one. Finished work is
// taken by the UI thread, which only uploads it (the CPU half of the object is prepared here).
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/progress.hpp"
#include "params/object_params.hpp"
#include "render/object_gpu.hpp"
#include "stipple/object_data.hpp"

namespace stipple::app {

struct FinishedWork {
    enum class Kind { Regenerated, Loaded, Failed };
    Kind kind = Kind::Failed;
    uint64_t object_id = 0;  // Regenerated: the object it was made for
    std::string path;        // Loaded and Failed loads: the model file
    ObjectParams params;     // what it was made with
    ObjectData data;         // the stipples (and for a load the mesh and bounds)
    std::unique_ptr<ObjectUpload> upload;  // staged, ready for the UI thread to upload
    std::string error;       // Failed: the one-line message
};

class BackgroundWork {
public:
    explicit BackgroundWork(const gpu::Context& context);  // it stages uploads (no queue use)
    ~BackgroundWork();  // cancels the running job and joins the worker
    BackgroundWork(const BackgroundWork&) = delete;
    BackgroundWork& operator=(const BackgroundWork&) = delete;

    // New stipples for a loaded model (its mesh, and an animated one's motion: its headroom shapes them).
    void regenerate(uint64_t object_id, const ObjectData& model, const ObjectParams& params);
    // `planned_before`: the bytes to check the model beside (LiveScene::planned_beyond_held).
    void load(const std::string& path, const ObjectParams& params, uint64_t planned_before = 0);

    std::vector<FinishedWork> take_finished();
    // What runs now, e.g. "new stipples for stanford-bunny.obj", and how far it is; nothing when idle.
    struct Status {
        std::string label;
        double fraction = 0.0;
        size_t queued = 0;
    };
    std::optional<Status> status() const;
    // No job running or queued and nothing finished waiting to be taken.
    bool idle() const;

private:
    struct Job {
        FinishedWork::Kind kind;
        uint64_t object_id = 0;
        std::string path;
        ObjectData model;  // regenerations: the mesh and motion (no stipples)
        ObjectParams params;
        std::string label;
        uint64_t planned_before = 0;  // loads: check_model_fits beside these bytes
    };
    void run();
    FinishedWork execute(const Job& job);

    const gpu::Context& context_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Job> queue_;
    std::optional<Job> running_;
    std::shared_ptr<ProgressObserver> observer_;  // the running job's
    std::vector<FinishedWork> finished_;
    bool stopping_ = false;
    std::thread worker_;
};

}  // namespace stipple::app
