#include "anim/headroom.hpp"

#include <algorithm>
#include <cstdio>

#include "anim/stretch.hpp"
#include "core/error.hpp"

namespace stipple::anim {

StretchHeadroom measure_headroom(const AnimatedModel& model, float cap) {
    StretchHeadroom headroom;
    headroom.cap = cap;
    const Mesh& rest = model.rest;
    const size_t triangles = rest.triangle_count();
    std::vector<float> largest(triangles, 1.0f);
    std::vector<uint8_t> opened(triangles, 0);
    headroom.bounds = compute_bounds(rest);
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const StretchReport report = measure_stretch(model, static_cast<int>(a));
        for (size_t t = 0; t < triangles; ++t) {
            largest[t] = std::max(largest[t], report.max_area_ratio[t]);
            opened[t] |= report.opened[t];
        }
        if (report.max_ratio > headroom.max_ratio) {
            headroom.max_ratio = report.max_ratio;
            headroom.max_animation = model.animations[a].name;
        }
        const auto in_range = [](const glm::vec3& p) {
            return glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(kMaxCoordinate)));  // false for NaN too
        };
        if (headroom.out_of_range.empty() && !(in_range(report.bounds.min) && in_range(report.bounds.max)))
            headroom.out_of_range = "animation " + std::to_string(a) + " " + quoted_excerpt(model.animations[a].name, 120);
        headroom.bounds.min = glm::min(headroom.bounds.min, report.bounds.min);
        headroom.bounds.max = glm::max(headroom.bounds.max, report.bounds.max);
    }
    headroom.opened_triangles = static_cast<size_t>(std::count(opened.begin(), opened.end(), uint8_t(1)));
    headroom.per_triangle.resize(triangles);
    double weighted = 0.0, area = 0.0;
    for (size_t t = 0; t < triangles; ++t) {
        // A ratio within float noise of 1 is no stretch: such polygons stay exactly as a static model's.
        const float ratio = largest[t] > 1.0f + 1e-4f ? largest[t] : 1.0f;
        headroom.per_triangle[t] = std::min(ratio, cap);
        headroom.stretched_triangles += ratio > 1.0f;
        headroom.capped_triangles += ratio > cap;
        const double a = triangle_area(rest, t);
        weighted += a * headroom.per_triangle[t];
        area += a;
    }
    headroom.candidate_factor = area > 0.0 ? weighted / area : 1.0;
    return headroom;
}

std::string describe_headroom(const StretchHeadroom& h, size_t triangles) {
    // The name as one printable line of bounded length: it goes into a fixed-size line below.
    const std::string where = h.max_animation.empty() ? std::string() : " (" + quoted_excerpt(h.max_animation, 120) + ")";
    char line[320];
    std::snprintf(line, sizeof line,
                  "polygons reach up to %.2fx their rest area%s; candidates generated for up to %.3gx: %zu of %zu "
                  "polygons stretched, %zu capped; %.2fx the static candidates",
                  double(h.max_ratio), where.c_str(), double(h.cap), h.stretched_triangles, triangles,
                  h.capped_triangles, h.candidate_factor);
    if (h.opened_triangles == 0) return line;
    const bool one = h.opened_triangles == 1;
    return line + std::string("; ") + std::to_string(h.opened_triangles) + (one ? " polygon" : " polygons") +
           " of no area at rest " + (one ? "opens" : "open") + " in an animation and " + (one ? "is" : "are") +
           " drawn without stipples";
}

}  // namespace stipple::anim
