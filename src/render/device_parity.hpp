#pragma once
// Do two Vulkan devices draw the same stipples (issue 17: lavapipe against a real GPU)? The same object,
// views and density paths on each device, with every drawn stipple counted on the GPU and the mean ink
// inside the coverage mask measured; then, per view, the drawn counts, the drawn sets (by stipple
// identity) and the mean ink compared. Used by `stipple parity` and its test.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "anim/headroom.hpp"
#include "mesh/mesh.hpp"
#include "params/object_params.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple {

namespace gpu {
class Context;
}

struct ParityView {
    float yaw_deg = 0.0f, pitch_deg = 0.0f;
    DensityPath path = DensityPath::Splat;
};

// Yaws all around at two elevations, on each path.
std::vector<ParityView> parity_views(int yaws, const std::vector<DensityPath>& paths);

struct ParitySample {
    int64_t drawn = 0;             // stipples drawn (the GPU's count)
    double mean_ink = 0.0;         // inside the coverage mask
    std::vector<uint32_t> mask;    // which stipples were drawn, one bit each
};

struct DeviceRun {
    std::string device;                // the device's name
    std::vector<ParitySample> samples;  // one per view
};

// The object (framed on `bounds`, default look but `params`) drawn on `context` in every view.
DeviceRun run_parity_views(const gpu::Context& context, const Mesh& mesh, const StippleSet& stipples,
                           const Sphere& bounds, const ObjectParams& params, VkExtent2D extent,
                           const std::vector<ParityView>& views, const anim::Motion& motion = {});

struct ParityRow {
    ParityView view;
    int64_t drawn_a = 0, drawn_b = 0;
    double count_difference = 0.0;  // |a - b| / a
    double set_difference = 0.0;    // stipples drawn by one device only / a's drawn
    double ink_a = 0.0, ink_b = 0.0;
    double ink_difference = 0.0;    // |a - b| / a
};

// The parity: drawn counts within 0.1%, mean ink within 1%, in every view.
inline constexpr double kParityCountLimit = 0.001;
inline constexpr double kParityInkLimit = 0.01;

struct ParityReport {
    std::vector<ParityRow> rows;
    double worst_count = 0.0, worst_set = 0.0, worst_ink = 0.0;
    bool holds() const { return worst_count <= kParityCountLimit && worst_ink <= kParityInkLimit; }
};

ParityReport compare_parity(const DeviceRun& a, const DeviceRun& b, const std::vector<ParityView>& views);

}  // namespace stipple
