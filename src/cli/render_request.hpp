#pragma once
// What `stipple render` is asked to write and how, read from its options and checked before any model is
// read (a long generation must not end in "that option is for another output").
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/frame_export.hpp"
#include "cli/args.hpp"
#include "export/plot_file.hpp"
#include "render/depth_raster.hpp"
#include "render/depth_triangles.hpp"
#include "scene/scene.hpp"

namespace stipple::cli {

struct RenderRequest {
    std::string output;  // -o / --output: a PNG, or vector output (.svg, .pdf, .csv); a pattern for a sequence
    bool vector = false;  // -o names vector output
    plot::ExportOptions vector_options;
    std::optional<app::PrintOptions> print;  // --dpi with --page: a print-resolution PNG
    long long width = 1280, height = 1024;
    bool print_of_page_shape = false;  // a print whose frame takes the page's shape (no --width)
    long long device = -1;
    long long repeat = 0;  // --repeat: frames timed after the first
    long long queued = 0;  // 0: by the device (OffscreenTarget::default_queued_frames)
    long long frames = 0;  // --frames: 0 for a single frame
    DepthCull depth_cull = DepthCull::Auto;
    DepthRaster depth_raster = DepthRaster::Auto;
    std::optional<float> orbit;  // --orbit: degrees turned over the frames
};

// Fails (stipple::Error) with a one-line message naming the option on any value out of range or option that
// does not apply to the output asked.
RenderRequest read_render_request(const Args& args);

// A frame sequence's -o (and --mask) must hold a frame number, and no mask frame may name an image frame's
// file.
void check_sequence_patterns(const Args& args, const std::string& output, size_t frame_count);

// The warnings of a drawing that will not show (nothing asked, ink the paper's colour, light ink on an
// unpainted page), said once before any work; and each object's ink.
struct SceneInks {
    bool draws_nothing = false;  // D_max 0 everywhere, no line and no toon
    bool one_colour = false;     // every object's ink is the paper's colour
    std::vector<glm::vec3> inks;  // by object: its own ink, else the scene's
};
SceneInks warn_about_scene_inks(const Scene& scene, const RenderRequest& request, const std::string& what);

// A single frame reads -o as a pattern where it is one (%% a literal %, %d the frame number) and keeps it
// as written where it is not (50%.png).
std::string output_path(const std::string& pattern, size_t index, bool sequence);

// The same file however it is named (relative, absolute, through a link).
bool same_file(const std::string& a, const std::string& b);

}  // namespace stipple::cli
