#pragma once
// Synthetic blue-noise dot sets (Poisson-disc, Bridson's dart throwing), the kind of set a
// stippled surface projects to: the plotter order's tests and speed tool measure on them.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace stipple::plot {

// A maximal Poisson-disc set in [0,width)x[0,height) whose points are at least `spacing` apart.
std::vector<glm::dvec2> poisson_disc_points(double width, double height, double spacing, uint32_t seed);

// The spacing for which poisson_disc_points gives about `count` points in that rectangle.
double poisson_disc_spacing(double width, double height, size_t count);

}  // namespace stipple::plot
