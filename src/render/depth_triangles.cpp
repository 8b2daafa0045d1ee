#include "render/depth_triangles.hpp"

#include <algorithm>

#include "render/descriptor_schema.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

const char* depth_cull_name(DepthCull mode) {
    switch (mode) {
        case DepthCull::On: return "on";
        case DepthCull::Off: return "off";
        case DepthCull::Auto: break;
    }
    return "auto";
}

std::optional<DepthCull> parse_depth_cull(const std::string& name) {
    for (DepthCull mode : {DepthCull::Auto, DepthCull::On, DepthCull::Off})
        if (name == depth_cull_name(mode)) return mode;
    return std::nullopt;
}

float mean_front_triangle_px(const ObjectGpu& object, const gpu::ObjectUniforms& uniforms, const FrameView& view) {
    const ObjectGeometry& g = object.geometry;
    const float depth = uniforms.intrinsic.z;  // view depth of the object's centre
    if (g.triangle_count == 0 || depth <= uniforms.intrinsic.y) return 0.0f;  // the eye within its sphere
    // Pixels per world unit at the centre's depth, in the image's own pixels (a tile's projection
    // scales back up to the full image, as FrameUniforms::projection does).
    const float pixels_per_unit = view.camera.proj[1][1] * 0.5f * float(view.extent.height) / scaling_depth(view.camera, depth);
    const float world_area = g.surface_area * uniforms.extrinsic.w;
    return 0.5f * world_area * pixels_per_unit * pixels_per_unit / float(g.triangle_count);
}

bool may_list_depth_triangles(const ObjectGpu& object) {
    return object.geometry.index_count > 0 && !object.params.toon;
}

bool DepthCullChooser::next_frame(float mean_px) {
    awaiting_ = false;
    if (mean_px <= 0.0f) {  // nothing to list: start afresh when something is
        phase_ = Phase::Timing;
        fresh_ = true;
        return listed_ = false;
    }
    if (phase_ == Phase::Holding) {
        const float change = mean_px / decided_px_;
        if (--hold_left_ > 0 && change < 1.5f && change > 1.0f / 1.5f) return listed_;
        phase_ = Phase::Timing;
        fresh_ = true;
    }
    if (fresh_) {
        fresh_ = false;
        guess_ = mean_px < kDepthCullBelowPx;
        frame_ = 0;
        best_ms_[0] = best_ms_[1] = 0.0;
    }
    // Frame 0 (untimed: a first frame pays for what later ones reuse) takes the guess, then the two
    // alternate.
    listed_ = frame_ % 2 == 0 ? guess_ : !guess_;
    awaiting_ = true;
    decided_px_ = mean_px;
    return listed_;
}

void DepthCullChooser::frame_done(double depth_ms) {
    if (!awaiting_ || phase_ != Phase::Timing) return;
    awaiting_ = false;
    if (frame_ > 0) {  // the fastest of each: a software GPU's frames vary by a fifth, upwards
        double& best = best_ms_[listed_ ? 1 : 0];
        best = best > 0.0 ? std::min(best, depth_ms) : depth_ms;
    }
    if (++frame_ <= kDepthCullTimedFrames) return;
    listed_ = best_ms_[1] < best_ms_[0];
    phase_ = Phase::Holding;
    hold_left_ = kDepthCullHoldFrames;
}

void ensure_depth_triangles(ObjectGpu& object) {
    const VkDeviceSize bytes =
        sizeof(gpu::DepthTriangles) + sizeof(uint32_t) * VkDeviceSize(object.geometry.index_count);
    if (bytes <= object.frame.depth_triangles.size()) return;
    object.frame.depth_triangles = make_index_list_buffer(*object.context, bytes);
    write_object_descriptors(object);
}

}  // namespace stipple
