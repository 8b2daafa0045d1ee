#pragma once
// The CPU reference deformation: what shaders/deform.comp computes, in double precision. Morph deltas
// are added in each vertex's own space, then the weighted sum of its palette matrices moves it to object
// space; normals go through that blended matrix's inverse transpose and are renormalised.
#include <vector>

#include <glm/glm.hpp>

#include "anim/animated_model.hpp"
#include "anim/pose.hpp"

namespace stipple::anim {

struct DeformedGeometry {
    std::vector<glm::vec3> positions;  // per rest vertex, object space
    std::vector<glm::vec3> normals;    // unit length
};

void deform_cpu(const AnimatedModel& model, const Pose& pose, DeformedGeometry& out);
DeformedGeometry deform_cpu(const AnimatedModel& model, const Pose& pose);

// The weighted sum of a vertex's palette matrices: what moves it from its own space to object space.
glm::dmat4 blend_matrix(const AnimatedModel& model, const Pose& pose, size_t vertex);

// One vertex (the loop body of deform_cpu, for callers that need only a few vertices).
void deform_vertex(const AnimatedModel& model, const Pose& pose, size_t vertex, glm::dvec3& position, glm::dvec3& normal);

}  // namespace stipple::anim
