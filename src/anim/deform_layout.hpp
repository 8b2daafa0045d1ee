#pragma once
// The deformation kernel's GPU layouts from shaders/deform_types.h, checked against std430.
#include <cstddef>

#include "deform_types.h"

namespace stipple::gpu {

static_assert(sizeof(DeformVertex) == 80);
static_assert(offsetof(DeformVertex, morph_first) == 12);
static_assert(offsetof(DeformVertex, normal) == 16);
static_assert(offsetof(DeformVertex, morph_weights) == 28);
static_assert(offsetof(DeformVertex, slots) == 32);
static_assert(offsetof(DeformVertex, weights0) == 48);
static_assert(offsetof(DeformVertex, weights1) == 64);

static_assert(sizeof(MorphDelta) == 32);
static_assert(offsetof(MorphDelta, normal) == 16);

static_assert(sizeof(DeformPush) == 16);
static_assert(sizeof(PolygonConstantsPush) == 48);
static_assert(offsetof(PolygonConstantsPush, box_size) == 16);
static_assert(offsetof(PolygonConstantsPush, triangle_count) == 32);
static_assert(kDeformMaxInfluences == 8);

}  // namespace stipple::gpu
