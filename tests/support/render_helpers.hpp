#pragma once
// Small helpers shared by the GPU tests: an object prepared for rendering and a framed view.
#include <glm/gtc/matrix_transform.hpp>

#include "mesh/mesh.hpp"
#include "render/offscreen.hpp"
#include "stipple/stipple_set.hpp"

namespace stipple::test {

struct Prepared {
    Mesh mesh;
    StippleSet stipples;
    glm::mat4 model{1.0f};
};

inline Prepared prepare(Mesh mesh, const ObjectParams& params, glm::mat4 model = glm::mat4(1.0f)) {
    Prepared p;
    p.stipples = generate_stipples(mesh, params.generation);
    p.mesh = std::move(mesh);
    p.model = model;
    return p;
}

// A camera framing `sphere` at `distance` times the framing distance.
inline FrameView framed_view(const Sphere& sphere, VkExtent2D extent, float distance = 1.0f, float yaw = 20.0f,
                             float pitch = 10.0f, bool orthographic = false) {
    float aspect = float(extent.width) / float(extent.height);
    FrameView view;
    view.extent = extent;
    view.camera = camera_matrices(frame_sphere(sphere, aspect, distance, yaw, pitch, OrbitCamera{}.fov_y_deg, orthographic),
                                  aspect, sphere);
    return view;
}

// Mean darkness (1 - luminance) over the covered pixels: the tone, fractional stipples included.
inline double mean_ink(const RenderedFrame& frame) {
    double sum = 0.0;
    size_t covered = 0;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        if (frame.depth[i] >= 1.0f) continue;
        ++covered;
        sum += 1.0 - frame.color.pixels[4 * i] / 255.0;
    }
    return covered ? sum / double(covered) : 0.0;
}

inline size_t popcount(const std::vector<uint32_t>& mask) {
    size_t n = 0;
    for (uint32_t w : mask) n += size_t(__builtin_popcount(w));
    return n;
}

}  // namespace stipple::test
