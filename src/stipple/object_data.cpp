#include "stipple/object_data.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <new>

#include "anim/animated_model.hpp"
#include "anim/gltf_probe.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/printf_string.hpp"
#include "core/timing.hpp"
#include "mesh/load_mesh.hpp"
#include "stipple/stipple_cache.hpp"

namespace stipple {

namespace {

bool is_gltf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".gltf" || ext == ".glb";
}

// The smallest sphere around a box: an animated model's bounds hold every pose, not one.
Sphere box_sphere(const Bounds& box) { return Sphere{box.center(), 0.5f * glm::length(box.max - box.min)}; }

// load_model_data, without naming the file when memory runs out.
ObjectData read_model(const std::string& path) {
    ObjectData object;
    const auto start = Clock::now();
    if (is_gltf(path) && anim::gltf_declares_deformation(path)) {
        // One read serves both: the animated loader's rest mesh is load_mesh_for_drawing's, with the
        // skins and default morph weights applied where the file's rest pose differs from it.
        auto model = std::make_shared<anim::AnimatedModel>(anim::load_animated_model(path));
        if (model->is_animated()) {
            object.motion.headroom = std::make_shared<const anim::StretchHeadroom>(anim::measure_headroom(*model));
            if (!object.motion.headroom->out_of_range.empty())
                fail_file(path, object.motion.headroom->out_of_range + " moves the model beyond the +-" +
                                    printf_string("%g", double(kMaxCoordinate)) + " a coordinate may reach");
            object.motion.model = model;
            object.mesh = std::shared_ptr<const Mesh>(object.motion.model, &object.motion.model->rest);
            object.bounds = box_sphere(object.motion.headroom->bounds);
            object.box = object.motion.headroom->bounds;
        } else {
            // What glTF would show (the rest pose) cannot be drawn and nothing moves it: say so where it is drawn,
            // not only in info.
            if (model->rest_pose_declined)
                std::fprintf(stderr, "%s: warning: its rest pose (skins and default morph weights applied) collapses faces "
                                     "or leaves the coordinates drawing allows, and no animation moves it: drawn as stored\n",
                             excerpt(path, 400).c_str());
            object.still = anim::describe_animation(*model);
            object.mesh = std::make_shared<const Mesh>(std::move(model->rest));
        }
    } else {
        object.mesh = std::make_shared<const Mesh>(load_mesh_for_drawing(path));
    }
    if (!object.motion) object.bounds = compute_bounding_sphere(*object.mesh), object.box = compute_bounds(*object.mesh);
    // In the file's coordinates, as the scene's transform reads them (a model stored about its own centre).
    const glm::vec3 origin(object.mesh->origin);
    object.bounds.center += origin, object.box.min += origin, object.box.max += origin;
    object.load_seconds = seconds_since(start);
    return object;
}

}  // namespace

std::shared_ptr<const Mesh> load_drawing_mesh(const std::string& path, double* seconds) {
    const auto start = Clock::now();
    auto mesh = std::make_shared<const Mesh>(load_mesh_for_drawing(path));
    if (seconds) *seconds = seconds_since(start);
    return mesh;
}

ObjectData load_model_data(const std::string& path) {
    try {
        return read_model(path);
    } catch (const std::bad_alloc&) {
        fail_out_of_memory(path);  // the probe's and the animated loader's reading too
    }
}

ObjectData reflected_object(const ObjectData& model) {
    STIPPLE_CHECK(model.mesh != nullptr, "a loaded model");
    if (model.motion)
        fail_file(model.mesh->source, "is animated, and an animated model cannot be mirrored (its animation moves the "
                                      "stored mesh): mirror it in its file");
    ObjectData reflected;
    reflected.mesh = std::make_shared<const Mesh>(reflected_through_origin(*model.mesh));
    reflected.bounds = {-model.bounds.center, model.bounds.radius};
    reflected.box = {-model.box.max, -model.box.min};
    reflected.load_seconds = model.load_seconds;
    return reflected;
}

std::shared_ptr<const StippleSet> make_stipples(const Mesh& mesh, const GenerationParams& generation,
                                                StippleSource source, std::span<const float> headroom) {
    GenerationParams params = generation;
    params.progress = mesh.triangle_count() > kProgressBarTriangles;  // big models take seconds: show it
    if (source == StippleSource::Cache)
        return std::make_shared<const StippleSet>(
            generate_stipples_cached(mesh, params, headroom));
    const auto start = Clock::now();
    StippleSet set = generate_stipples(mesh, params, headroom);
    finish_generated_stipples(mesh, params.seed, set);  // the selection values of §2.3, as the cache keeps them
    set.generation_seconds = seconds_since(start);               // the ranking counts as preprocessing
    return std::make_shared<const StippleSet>(std::move(set));
}

namespace {

// An animated model's stretch headroom per triangle (generate_stipples); empty for a static one.
std::span<const float> stretch_headroom(const ObjectData& model) {
    return model.motion ? std::span<const float>(model.motion.headroom->per_triangle) : std::span<const float>();
}

}  // namespace

std::shared_ptr<const StippleSet> make_stipples(const ObjectData& model, const GenerationParams& generation,
                                                StippleSource source) {
    return make_stipples(*model.mesh, generation, source, stretch_headroom(model));
}

uint64_t planned_stipple_count(const ObjectData& model, const GenerationParams& generation) {
    return planned_stipple_count(*model.mesh, generation, stretch_headroom(model));
}

void check_generation_fits_memory(const std::string& path, uint64_t count) {
    const uint64_t memory = physical_memory_bytes();
    const uint64_t most = memory / kGenerationBytesPerStipple;
    if (memory == 0 || count <= most) return;
    fail_file(path, std::to_string(count) + " stipples planned, whose generation needs about " +
                        byte_size(count * kGenerationBytesPerStipple) + " (" + std::to_string(kGenerationBytesPerStipple) +
                        " bytes a stipple), more than this machine's " + byte_size(memory) + " of memory holds (at most " +
                        std::to_string(most) + " stipples): lower --dmax or --max-stipples");
}

std::shared_ptr<const StippleSet> make_model_stipples(const std::string& path, const ObjectData& model,
                                                      const GenerationParams& generation, StippleSource source) {
    // Counted before, not in the handler: for a mesh outside the unit frame the count copies the mesh, which
    // memory that just ran out may not hold.
    const uint64_t planned = planned_stipple_count(model, generation);
    check_generation_fits_memory(path, planned);
    try {
        return make_stipples(model, generation, source);
    } catch (const std::bad_alloc&) {
        fail_file(path, "out of memory generating its " + std::to_string(planned) + " stipples: lower --dmax or --max-stipples");
    }
}

ObjectData load_object_data(const std::string& path, const GenerationParams& generation, StippleSource source) {
    ObjectData object = load_model_data(path);
    object.stipples = make_model_stipples(path, object, generation, source);
    return object;
}

}  // namespace stipple
