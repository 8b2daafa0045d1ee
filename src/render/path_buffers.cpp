#include "render/path_buffers.hpp"

#include "render/descriptor_schema.hpp"
#include "render/object_gpu.hpp"

namespace stipple {

using gpu::Buffer;
using gpu::MemoryUse;

const char* path_buffer_name(PathBuffer kind) {
    switch (kind) {
        case PathBuffer::DrawnPolygons: return "drawn_polygons";
        case PathBuffer::DrawStaging: return "draw_staging";
        case PathBuffer::GradientPolygons: return "gradient_polygons";
        case PathBuffer::SplatRing: return "splat_ring";
        case PathBuffer::DrawnStipples: break;
    }
    return "drawn_stipples";
}

Buffer& path_buffer(ObjectFrame& frame, PathBuffer kind) {
    switch (kind) {
        case PathBuffer::DrawnPolygons: return frame.drawn_polygons;
        case PathBuffer::DrawStaging: return frame.draw_staging;
        case PathBuffer::GradientPolygons: return frame.gradient_polygons;
        case PathBuffer::SplatRing: return frame.splat_ring;
        case PathBuffer::DrawnStipples: break;
    }
    return frame.drawn_stipples;
}

const Buffer& path_buffer(const ObjectFrame& frame, PathBuffer kind) {
    return path_buffer(const_cast<ObjectFrame&>(frame), kind);
}

VkDeviceSize path_buffer_bytes(const ObjectGpu& object, DensityPath path, PathBuffer kind) {
    const VkDeviceSize n = object.geometry.triangle_count;
    // At most one splat work item per polygon plus one per kSplatShortRun candidates (gpu::DrawnPolygons).
    const VkDeviceSize items = n + object.geometry.stipple_count / gpu::kSplatShortRun;
    const VkDeviceSize list = sizeof(gpu::DrawnPolygons) + sizeof(uint32_t) * items;
    // Every candidate may draw (a close-up), each listed once.
    const VkDeviceSize survivors = sizeof(gpu::DrawCommand) + sizeof(uint32_t) * VkDeviceSize(object.geometry.stipple_count);
    const bool lists_survivors = path == DensityPath::Cpu || path == DensityPath::Indirect;
    // The vertex path's chunks of the polygons whose density changes across them (GradientChunks).
    const VkDeviceSize chunks = sizeof(gpu::DrawCommand) + sizeof(uint32_t) * (n + object.geometry.stipple_count / gpu::kGradientChunk);
    switch (kind) {
        // The indirect path lists its stipples from the same work items.
        case PathBuffer::DrawnPolygons: return draws_by_splat(path) || path == DensityPath::Indirect ? list : 0;
        case PathBuffer::DrawStaging:
            if (path == DensityPath::Cpu) return staged_list_offset(object) + survivors;
            return path == DensityPath::CpuSplat ? staged_list_offset(object) + list : 0;
        // The splat with GPU densities: the work items of the polygons whose density varies across them,
        // listed apart (splat.comp kSplatListVarying; every polygon's, at most).
        case PathBuffer::DrawnStipples:
            return lists_survivors ? survivors : path == DensityPath::Vertex ? chunks : path == DensityPath::Splat ? list : 0;
        // The work items with a dot astride the outline, for the splat's ring pass: one per item at most.
        case PathBuffer::SplatRing: return draws_by_splat(path) ? list : 0;
        // The density pass's list of polygons large on screen (every polygon at most) for its gradient pass.
        case PathBuffer::GradientPolygons:
            return density_on_cpu(path) ? 0 : sizeof(gpu::DrawnPolygons) + sizeof(uint32_t) * n;
    }
    return 0;
}

Buffer make_path_buffer(const gpu::Context& context, PathBuffer kind, VkDeviceSize bytes) {
    const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const auto indirect = VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    const auto destination = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    switch (kind) {
        case PathBuffer::DrawStaging: return Buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Upload);
        case PathBuffer::DrawnPolygons:
        case PathBuffer::DrawnStipples:
        case PathBuffer::GradientPolygons:
        case PathBuffer::SplatRing: break;
    }
    // Written by a compute pass or copied from the staging buffer, read as indirect arguments.
    return Buffer(context, bytes, storage | indirect | destination, MemoryUse::DeviceLocal);
}

void ensure_path_buffers(ObjectGpu& object, DensityPath path) {
    bool grown = false;
    for (PathBuffer kind : kPathBuffers) {
        VkDeviceSize bytes = path_buffer_bytes(object, path, kind);
        Buffer& buffer = path_buffer(object.frame, kind);
        if (bytes <= buffer.size()) continue;
        buffer = make_path_buffer(*object.context, kind, bytes);
        grown = true;
    }
    if (grown) write_object_descriptors(object);
}

VkDeviceSize staged_list_offset(const ObjectGpu& object) {
    return sizeof(gpu::TriangleDraw) * VkDeviceSize(object.geometry.triangle_count);
}

}  // namespace stipple
