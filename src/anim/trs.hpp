#pragma once
// A node's local matrix from translation, rotation and scale: T * R * S, as glTF defines it. Shared
// by the loader (rest pose) and the evaluation (animated pose), and computed exactly as the static
// glTF loader computes it, so that the rest pose reproduces the static mesh to the last bit.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace stipple::anim {

inline glm::dmat4 trs_matrix(const glm::dvec3& translation, const glm::dquat& rotation, const glm::dvec3& scale) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(translation, 1.0);
    m = m * glm::mat4_cast(rotation);
    return m * glm::scale(glm::dmat4(1.0), scale);
}

}  // namespace stipple::anim
