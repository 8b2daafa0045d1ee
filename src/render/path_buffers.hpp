#pragma once
// The buffers only some density paths use. Every object holds a placeholder of each (the descriptor
// set needs a buffer in every binding) and grows one to full size when the object first draws with a
// path that uses it: an object costs only what its paths need.
#include <vulkan/vulkan.h>

#include "gpu/resources.hpp"
#include "params/object_params.hpp"

namespace stipple {

struct ObjectGpu;
struct ObjectFrame;

inline constexpr VkDeviceSize kPathBufferPlaceholderBytes = 32;

enum class PathBuffer { DrawnPolygons, DrawStaging, DrawnStipples, GradientPolygons, SplatRing };
inline constexpr PathBuffer kPathBuffers[] = {PathBuffer::DrawnPolygons, PathBuffer::DrawStaging,
                                              PathBuffer::DrawnStipples, PathBuffer::GradientPolygons,
                                              PathBuffer::SplatRing};

const char* path_buffer_name(PathBuffer kind);
gpu::Buffer& path_buffer(ObjectFrame& frame, PathBuffer kind);
const gpu::Buffer& path_buffer(const ObjectFrame& frame, PathBuffer kind);

// The bytes `path` needs in that buffer (0: the path does not use it).
VkDeviceSize path_buffer_bytes(const ObjectGpu& object, DensityPath path, PathBuffer kind);

// A buffer of that kind, with the usage its path needs.
gpu::Buffer make_path_buffer(const gpu::Context& context, PathBuffer kind, VkDeviceSize bytes);

// Grows the buffers `path` uses to their full size (rewriting the descriptor set); the GPU must not be
// using the object (StippleRenderer::prepare's contract).
void ensure_path_buffers(ObjectGpu& object, DensityPath path);

// Where draw_staging holds the list the CPU writes after the densities: the cpu-splat path's work list
// (DrawnPolygons header, then the items) or the cpu path's survivors (DrawCommand, then the stipples).
VkDeviceSize staged_list_offset(const ObjectGpu& object);

}  // namespace stipple
