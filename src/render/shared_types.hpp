#pragma once
// The GPU-visible layouts from shaders/shared_types.h, checked against what GLSL's std140/std430
// and the vertex input layout expect.
#include <cstddef>

#include <vulkan/vulkan.h>

#include "shared_types.h"

namespace stipple::gpu {

static_assert(sizeof(StippleVertex) == 8);
static_assert(offsetof(StippleVertex, barycentric) == 0);
static_assert(offsetof(StippleVertex, triangle) == 4);

static_assert(sizeof(TriangleDraw) == 16);
static_assert(offsetof(TriangleDraw, density) == 0);
static_assert(offsetof(TriangleDraw, first_stipple) == 4);
static_assert(offsetof(TriangleDraw, least) == 8);
static_assert(offsetof(TriangleDraw, most) == 12);

static_assert(sizeof(TriangleInfo) == 16);
static_assert(offsetof(TriangleInfo, center_z_selection) == 4);
static_assert(offsetof(TriangleInfo, normal) == 8);
static_assert(offsetof(TriangleInfo, area) == 12);

static_assert(sizeof(DrawnPolygons) == 16);
static_assert(offsetof(DrawnPolygons, count) == 12);

static_assert(sizeof(SilhouetteEdge) == 16);
static_assert(offsetof(SilhouetteEdge, second_polygon) == 12);
static_assert(sizeof(IndexList) == kIndexListHeaderBytes);
static_assert(sizeof(RasterTriangles) == kIndexListHeaderBytes);  // shares the depth list's buffer
static_assert(offsetof(RasterTriangles, count) == 12);
static_assert(offsetof(IndexList, first_instance) == 16);
static_assert(kIndexListFirstIndex * sizeof(uint32_t) == sizeof(IndexList));  // indices right after it
// The Raskar-Cohen caps read the silhouette list's header as a VkDrawIndirectCommand (line_passes.cpp): index_count
// as vertexCount, first_index as firstVertex, vertex_offset (always 0) as firstInstance.
static_assert(offsetof(IndexList, index_count) == offsetof(VkDrawIndirectCommand, vertexCount));
static_assert(offsetof(IndexList, instance_count) == offsetof(VkDrawIndirectCommand, instanceCount));
static_assert(offsetof(IndexList, first_index) == offsetof(VkDrawIndirectCommand, firstVertex));
static_assert(offsetof(IndexList, vertex_offset) == offsetof(VkDrawIndirectCommand, firstInstance));

static_assert(sizeof(LineCandidates) == 16);
static_assert(offsetof(LineCandidates, count) == 12);
static_assert(sizeof(LinePiecesHeader) == 32);
static_assert(offsetof(LinePiecesHeader, capacity) == 16);
static_assert(sizeof(LinePiece) == 24);
static_assert(offsetof(LinePiece, edge) == 16);

static_assert(sizeof(DebugCounters) == 16);
static_assert(offsetof(DebugCounters, drawn) == 0);

static_assert(sizeof(VisibleStipplesHeader) == 16);
static_assert(sizeof(VisibleStipple) == 20);
static_assert(offsetof(VisibleStipple, intensity) == 8);
static_assert(offsetof(VisibleStipple, index) == 12);
static_assert(offsetof(VisibleStipple, scale) == 16);

static_assert(sizeof(DrawCommand) == 16);
static_assert(offsetof(DrawCommand, first_vertex) == 8);

static_assert(sizeof(FrameUniforms) == 2 * 64 + 4 * 16);
static_assert(offsetof(FrameUniforms, view) == 64);
static_assert(offsetof(FrameUniforms, light_view) == 128);
static_assert(offsetof(FrameUniforms, paper_color) == 144);
static_assert(offsetof(FrameUniforms, viewport) == 160);
static_assert(offsetof(FrameUniforms, projection) == 176);

static_assert(sizeof(ObjectUniforms) == 3 * 64 + 8 * 16);
static_assert(offsetof(ObjectUniforms, normal_view) == 64);
static_assert(offsetof(ObjectUniforms, model_view_proj) == 128);
static_assert(offsetof(ObjectUniforms, shading) == 192);
static_assert(offsetof(ObjectUniforms, extrinsic) == 208);
static_assert(offsetof(ObjectUniforms, intrinsic) == 224);
static_assert(offsetof(ObjectUniforms, flags) == 240);
static_assert(offsetof(ObjectUniforms, box_min) == 256);
static_assert(offsetof(ObjectUniforms, box_size) == 272);
static_assert(offsetof(ObjectUniforms, lines) == 288);
static_assert(offsetof(ObjectUniforms, ink_color) == 304);

}  // namespace stipple::gpu
