#pragma once
// A direction given as any vector (the light's, on the command line or in a scene file), made unit
// length in double: its squared length in float overflows for components beyond ~1e19 (1e20,1e20,1e20
// lit the model from a wrong direction) and vanishes below ~1e-19 (1e-15,1e-15,1e-15 read as zero).
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

namespace stipple {

// The unit vector along v; nothing for a zero or non-finite v.
inline std::optional<glm::vec3> unit_direction(const glm::vec3& v) {
    const glm::dvec3 d(v);
    const double length = glm::length(d);
    if (!std::isfinite(length) || !(length > 0.0)) return std::nullopt;
    return glm::vec3(d / length);
}

}  // namespace stipple
