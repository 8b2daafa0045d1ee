#pragma once
// The C++ side of shaders/stipple_formulas.h: the very same source, compiled with glm's functions,
// so the CPU path and the shaders cannot drift apart.
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include "shared_types.h"

namespace stipple::formulas {
using namespace stipple::gpu;
using glm::abs;
using glm::ceil;
using glm::clamp;
using glm::cos;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::floor;
using glm::length;
using glm::log;
using glm::mat3;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::sign;
using glm::sin;
using glm::sqrt;
using glm::unpackSnorm2x16;
using glm::unpackUnorm2x16;
using std::pow;
#include "stipple_formulas.h"
}  // namespace stipple::formulas
