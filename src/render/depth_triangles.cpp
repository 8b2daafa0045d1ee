#include "render/depth_triangles.hpp"

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
    const float pixels_per_unit = view.camera.proj[1][1] * 0.5f * float(view.extent.height) / depth;
    const float world_area = g.surface_area * uniforms.extrinsic.w;
    return 0.5f * world_area * pixels_per_unit * pixels_per_unit / float(g.triangle_count);
}

bool uses_depth_triangles(const ObjectGpu& object, const gpu::ObjectUniforms& uniforms, const FrameView& view,
                          DepthCull mode) {
    if (object.geometry.index_count == 0 || object.params.toon || mode == DepthCull::Off) return false;
    if (mode == DepthCull::On) return true;
    const float px = mean_front_triangle_px(object, uniforms, view);
    return px > 0.0f && px < kDepthCullBelowPx;
}

void ensure_depth_triangles(ObjectGpu& object) {
    const VkDeviceSize bytes =
        sizeof(gpu::DepthTriangles) + sizeof(uint32_t) * VkDeviceSize(object.geometry.index_count);
    if (bytes <= object.frame.depth_triangles.size()) return;
    object.frame.depth_triangles = make_index_list_buffer(*object.context, bytes);
    write_object_descriptors(object);
}

}  // namespace stipple
