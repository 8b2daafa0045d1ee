#pragma once
// A model loaded for drawing and its stipples generated: the one place where every command (render,
// view, info, bench) and the viewer's drag-and-drop and regeneration do it.
#include <cstddef>
#include <memory>
#include <string>

#include "anim/describe.hpp"
#include "anim/headroom.hpp"
#include "mesh/mesh.hpp"
#include "params/object_params.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

// Models with more triangles than this show a progress bar while generating (on a terminal).
inline constexpr size_t kProgressBarTriangles = 200'000;

// Where stipples come from: the on-disk cache when it holds them (stipple_cache.hpp), or always a fresh
// generation (the benchmark times it). Both carry the polygons' selection values (§2.3).
enum class StippleSource { Cache, Generate };

// One object's CPU data. Meshes and stipple sets may be shared between objects that use the same
// model (and, for stipples, the same generation parameters): a scene may show one model many times.
struct ObjectData {
    std::shared_ptr<const Mesh> mesh;  // a glTF file's rest mesh (anim::AnimatedModel::rest)
    Sphere bounds;  // the file's coordinates (Mesh::origin added); an animated model's holds every pose of every animation
    Bounds box;     // the same points' box (scene framing under a matrix that scales axes unequally)
    std::shared_ptr<const StippleSet> stipples;
    anim::Motion motion;  // a glTF file with an animation: what moves it and its stretch headroom
    // A glTF file with skins, morph targets or animations of which none moves it (no animation, or channels
    // that drive nothing): what it holds, drawn in its rest pose (info says so); empty otherwise.
    anim::AnimationDescription still;
    double load_seconds = 0.0;  // reading and preparing the mesh (and measuring an animation's stretch)
};

// load_mesh_for_drawing, shared and timed.
std::shared_ptr<const Mesh> load_drawing_mesh(const std::string& path, double* seconds = nullptr);

// The model without stipples: its mesh, bounds and, for a glTF file with animations, its motion
// (load_animated_model and measure_headroom). A glTF file with animations, skins or morph weights is
// drawn from the animated loader's rest mesh (its rest pose), any other model from load_mesh_for_drawing.
ObjectData load_model_data(const std::string& path);
// A static model reflected through its origin for a mirroring scene transform (reflected_through_origin; its
// bounds the reflection of the model's, exactly, so that the up-axis turn about their centre commutes with
// it); no stipples yet. An animated model is refused: its joints move the stored rest mesh.
ObjectData reflected_object(const ObjectData& model);

// The stipples of `mesh` for `generation` (the progress flag is set here from the mesh's size);
// `headroom`: an animated model's (generate_stipples).
std::shared_ptr<const StippleSet> make_stipples(const Mesh& mesh, const GenerationParams& generation,
                                                StippleSource source = StippleSource::Cache,
                                                std::span<const float> headroom = {});
// The stipples of a loaded model, with its headroom when it moves.
std::shared_ptr<const StippleSet> make_stipples(const ObjectData& model, const GenerationParams& generation,
                                                StippleSource source = StippleSource::Cache);

// How many stipples make_stipples makes for this model (planned_stipple_count, with its headroom).
uint64_t planned_stipple_count(const ObjectData& model, const GenerationParams& generation);

// Generation's peak memory a stipple, the mesh and the program counted: 39.2-40.4 bytes for the 8M-stipple
// dragon (docs/performance.md, "Memory").
inline constexpr uint64_t kGenerationBytesPerStipple = 40;

// Refuses, in one line naming `path`, the count and the limit, `count` stipples whose generation would not fit
// in the machine's physical memory (or STIPPLE_HOST_MEMORY_LIMIT's): make_model_stipples's check, for callers
// that generate from a mesh of their own (the bench's rows).
void check_generation_fits_memory(const std::string& path, uint64_t count);

// make_stipples for the model loaded from `path`, refused first, in one line naming `path`, the count and the
// limit, where its planned stipples (planned_stipple_count) could not be generated in the machine's physical
// memory (`info stack.obj --max-stipples 2000000000` grew past 7 GB; render, tone and the viewer checked only
// the device's memory until 2026-12-06, which on a GPU of large buffers is not the tighter limit); memory
// that runs out while generating names the file and the stipples planned in one line too (a bare
// "stipple: out of memory" until 2026-12-06). The check comes before the stipple cache is read, so a cached
// set is refused where generating it would be.
std::shared_ptr<const StippleSet> make_model_stipples(const std::string& path, const ObjectData& model,
                                                      const GenerationParams& generation,
                                                      StippleSource source = StippleSource::Cache);

// Both: loads the model at `path` and makes its stipples (make_model_stipples).
ObjectData load_object_data(const std::string& path, const GenerationParams& generation,
                            StippleSource source = StippleSource::Cache);

}  // namespace stipple
