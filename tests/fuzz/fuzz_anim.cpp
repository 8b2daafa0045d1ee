// libFuzzer harness: the animated glTF loader on arbitrary bytes (.glb when they start with the GLB
// magic, else .gltf), then what loading an animated model runs next: every animation's poses (before,
// inside and past its keys, looped and not), the CPU deformation, the stretch headroom measured over
// every animation, and `stipple info`'s description. The static reader under it has a harness of its
// own (fuzz_gltf); this one reaches the skins, morph targets, samplers and channels.
#include <cstring>
#include <string>
#include <string_view>

#include "anim/animated_model.hpp"
#include "anim/deform_cpu.hpp"
#include "anim/describe.hpp"
#include "anim/headroom.hpp"
#include "anim/pose.hpp"
#include "fuzz_check.hpp"

namespace {

void exercise(const stipple::anim::AnimatedModel& model) {
    using namespace stipple;
    using namespace stipple::fuzz;
    check_mesh(model.rest);
    const size_t n = model.vertex_count();
    if (model.bind_positions.size() != n || model.bind_normals.size() != n || model.influences.size() != n ||
        model.morph_refs.size() != n)
        contract_broken("per-vertex streams do not match the rest mesh");
    for (const anim::MorphRef& ref : model.morph_refs)
        if (size_t(ref.first_delta) + ref.count > model.morph_deltas.size()) contract_broken("morph deltas out of range");
    // A handful of animations is every path a file can take; a file of thousands would only repeat them.
    const size_t animations = std::min<size_t>(model.animations.size(), 8);
    anim::DeformedGeometry out;
    for (size_t a = 0; a < animations; ++a) {
        const double duration = model.animations[a].duration;
        for (double t : {-0.5, 0.0, duration / 3.0, duration, duration * 1.7 + 0.01})
            for (bool loop : {true, false}) {
                anim::deform_cpu(model, anim::evaluate_pose(model, int(a), t, loop), out);
                if (out.positions.size() != n || out.normals.size() != n) contract_broken("deformed vertex count");
            }
    }
    if (model.is_animated()) {
        const anim::StretchHeadroom headroom = anim::measure_headroom(model);
        if (headroom.per_triangle.size() != model.rest.triangle_count()) contract_broken("headroom per triangle");
        (void)anim::describe_headroom(headroom, model.rest.triangle_count());
    }
    (void)anim::describe_lines(anim::describe_animation(model));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string name = glb ? "fuzz.glb" : "fuzz.gltf";
    stipple::LoadOptions options;
    options.max_elements = 4'000'000;
    try {
        exercise(stipple::anim::load_animated_model_from_bytes(
            name, std::string_view(reinterpret_cast<const char*>(data), size), options));
    } catch (const stipple::Error& e) {
        stipple::fuzz::check_message(e, name);
    }
    return 0;
}
