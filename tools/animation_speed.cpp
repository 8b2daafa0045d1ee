// Animation speed: loading (fox.glb), CPU evaluation per frame (pose + reference deformation), the GPU
// deformation kernel per frame, and the stretch measurement, on the fox and on a generated skinned
// cylinder of 100k+ vertices. Prints its figures; the test suite asserts results, never time.
// Usage: animation_speed [FOX.glb] [--rings R --segments S] [--frames N]
//   (default: ../shared/models/fox.glb, a 400 x 256 cylinder: 102,402 vertices, 205,312 triangles)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "anim/deform_cpu.hpp"
#include "anim/gpu_deform.hpp"
#include "anim/pose.hpp"
#include "anim/procedural_rigs.hpp"
#include "anim/stretch.hpp"
#include "core/error.hpp"
#include "gpu/context.hpp"
#include "gpu/gpu_timer.hpp"
#include "mesh/load_mesh.hpp"

namespace {

using namespace stipple;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// CPU: evaluation alone, and evaluation with the reference deformation, per frame at 30 fps.
void cpu_figures(const anim::AnimatedModel& model, int animation, int frames, const char* name) {
    anim::Pose pose;
    anim::DeformedGeometry g;
    std::vector<double> evaluate, deform;
    for (int f = 0; f < frames; ++f) {
        auto start = Clock::now();
        anim::evaluate_pose(model, animation, f / 30.0, true, pose);
        evaluate.push_back(ms_since(start));
        start = Clock::now();
        anim::deform_cpu(model, pose, g);
        deform.push_back(ms_since(start));
    }
    std::printf("%s: CPU per frame: pose %.4f ms, reference deformation %.3f ms (median of %d; fastest %.3f ms)\n", name,
                median(evaluate), median(deform), frames, *std::min_element(deform.begin(), deform.end()));
}

// GPU: the kernel's time from timestamps around its recording (palette upload included).
void gpu_figures(const gpu::Context& context, const anim::AnimatedModel& model, int animation, int frames, const char* name) {
    anim::GpuDeformer deformer(context, model);
    gpu::GpuTimer timer(context, 2);
    if (!timer.enabled()) {
        std::printf("%s: GPU: the device has no timestamps\n", name);
        return;
    }
    std::vector<double> kernel;
    for (int f = 0; f < frames; ++f) {
        const anim::Pose pose = anim::evaluate_pose(model, animation, f / 30.0);
        VkCommandBuffer cb = context.begin_one_shot();
        timer.begin_frame(cb);
        deformer.record(cb, pose);
        timer.mark(cb, "deform");
        context.submit_and_wait(cb);
        if (f > 0) kernel.push_back(timer.read().at(0).second);  // the first frame warms up
    }
    std::printf("%s: GPU deformation per frame %.3f ms (median of %zu; fastest %.3f ms; %s)\n", name, median(kernel),
                kernel.size(), *std::min_element(kernel.begin(), kernel.end()), context.device_name.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    std::string fox = std::string(STIPPLE_SOURCE_DIR) + "/../shared/models/fox.glb";
    anim::rigs::CylinderOptions cylinder;
    cylinder.rings = 400;
    cylinder.segments = 256;
    int frames = 60;
    const char* usage =
        "usage: animation_speed [FOX.glb] [--rings R --segments S] [--frames N]\n"
        "  times loading, posing and the GPU deformation of the fox (default ../shared/models/fox.glb) and of a\n"
        "  skinned cylinder of R x S vertices (default 400 x 256); prints figures only\n";
    for (int i = 1; i < argc; ++i) {
        const bool value = i + 1 < argc;
        if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            std::printf("%s", usage);
            return 0;
        }
        if (!std::strcmp(argv[i], "--rings") && value) cylinder.rings = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--segments") && value) cylinder.segments = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--frames") && value) frames = std::max(2, std::atoi(argv[++i]));
        else if (argv[i][0] == '-') {
            std::fprintf(stderr, "animation_speed: unknown or incomplete option '%s'\n%s", argv[i], usage);
            return 2;
        } else fox = argv[i];
    }
    try {
        gpu::ContextOptions options;
        const gpu::Context context(options);
        if (std::filesystem::exists(fox)) {
            std::vector<double> load, load_static;
            for (int i = 0; i < 5; ++i) {
                auto start = Clock::now();
                const anim::AnimatedModel model = anim::load_animated_model(fox);
                load.push_back(ms_since(start));
                start = Clock::now();
                const Mesh mesh = load_mesh_for_drawing(fox);
                load_static.push_back(ms_since(start));
            }
            const anim::AnimatedModel model = anim::load_animated_model(fox);
            std::printf("fox: %zu vertices, %zu triangles; load %.2f ms animated, %.2f ms static (median of 5)\n",
                        model.vertex_count(), model.rest.triangle_count(), median(load), median(load_static));
            const int run = anim::find_animation(model, "Run");
            cpu_figures(model, run, frames, "fox Run");
            gpu_figures(context, model, run, frames, "fox Run");
            const auto start = Clock::now();
            const anim::StretchReport stretch = anim::measure_stretch(model, run);
            std::printf("fox Run: stretch over %zu poses in %.1f ms: largest area ratio %.3f, smallest %.3f\n", stretch.times.size(),
                        ms_since(start), stretch.max_ratio, stretch.min_ratio);
        } else {
            std::printf("fox: %s not present, skipped\n", fox.c_str());
        }

        const std::string path = (std::filesystem::temp_directory_path() / "stipple-animation-speed-cylinder.glb").string();
        anim::rigs::bending_cylinder(cylinder).write(path);
        auto start = Clock::now();
        const anim::AnimatedModel model = anim::load_animated_model(path);
        const double load = ms_since(start);
        start = Clock::now();
        const Mesh mesh = load_mesh_for_drawing(path);
        std::printf("cylinder: %zu vertices, %zu triangles; load %.1f ms animated, %.1f ms static\n", model.vertex_count(),
                    model.rest.triangle_count(), load, ms_since(start));
        cpu_figures(model, 0, frames, "cylinder Bend");
        gpu_figures(context, model, 0, frames, "cylinder Bend");
        start = Clock::now();
        const anim::StretchReport stretch = anim::measure_stretch(model, 0);
        std::printf("cylinder Bend: stretch over %zu poses in %.1f ms: largest area ratio %.3f, smallest %.3f\n",
                    stretch.times.size(), ms_since(start), stretch.max_ratio, stretch.min_ratio);
        std::filesystem::remove(path);
    } catch (const Error& e) {
        std::fprintf(stderr, "animation_speed: %s\n", e.what());
        return 1;
    }
    return 0;
}
