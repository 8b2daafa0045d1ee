#include "anim/stretch.hpp"

#include <algorithm>
#include <cmath>

#include "anim/deform_cpu.hpp"
#include "anim/pose.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace stipple::anim {

std::vector<double> stretch_sample_times(const Animation& animation, uint32_t uniform, size_t max_key_times) {
    std::vector<double> times;
    const double duration = animation.duration;
    if (uniform == 1 || !(duration > 0.0)) times.push_back(0.0);
    else
        for (uint32_t i = 0; i < uniform; ++i) times.push_back(duration * i / (uniform - 1));
    std::vector<double> keys;
    for (const Channel& channel : animation.channels)
        for (float t : animation.samplers[channel.sampler].times)
            if (t >= 0.0f) keys.push_back(t);  // a key before 0 is never shown: time starts at 0
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    if (keys.size() > max_key_times && max_key_times > 0) {
        std::vector<double> thinned;
        const size_t last = std::max<size_t>(max_key_times - 1, 1);
        for (size_t i = 0; i < max_key_times; ++i) thinned.push_back(keys[i * (keys.size() - 1) / last]);
        keys.swap(thinned);
    }
    times.insert(times.end(), keys.begin(), keys.end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

StretchReport measure_stretch(const AnimatedModel& model, int animation, uint32_t uniform) {
    STIPPLE_CHECK(animation >= 0 && static_cast<size_t>(animation) < model.animations.size(), "animation index out of range");
    StretchReport report;
    report.times = stretch_sample_times(model.animations[animation], uniform);
    const Mesh& rest = model.rest;
    const size_t triangles = rest.triangle_count();
    std::vector<double> rest_area(triangles);
    double total_rest = 0.0;
    for (size_t t = 0; t < triangles; ++t) total_rest += rest_area[t] = triangle_area(rest, t);
    // A polygon of (next to) no area at rest has no candidates, whatever its ratio: 5e-41 at rest and 0.5
    // posed made a ratio beyond float range ("polygons reach up to infx", inf in info --json). Such a
    // polygon reports 1, and is counted where a pose opens it to a visible share of the surface.
    const double mean_rest = triangles > 0 ? total_rest / double(triangles) : 0.0;
    const double degenerate = 1e-9 * mean_rest, opened = 1e-3 * mean_rest;
    std::vector<uint8_t> opens(triangles, 0);
    report.max_area_ratio.assign(triangles, -INFINITY);
    report.min_area_ratio.assign(triangles, INFINITY);

    Pose pose;
    DeformedGeometry deformed;
    bool first = true;
    for (double time : report.times) {
        evaluate_pose(model, animation, time, /*loop=*/false, pose);
        deform_cpu(model, pose, deformed);
        parallel_for(triangles, 4096, [&](size_t t) {
            const glm::dvec3 a(deformed.positions[rest.indices[3 * t]]);
            const glm::dvec3 b(deformed.positions[rest.indices[3 * t + 1]]);
            const glm::dvec3 c(deformed.positions[rest.indices[3 * t + 2]]);
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
            double ratio = 1.0;
            if (rest_area[t] > degenerate) ratio = std::min(area / rest_area[t], 1e30);
            else if (area > opened) opens[t] = 1;
            report.max_area_ratio[t] = std::max(report.max_area_ratio[t], static_cast<float>(ratio));
            report.min_area_ratio[t] = std::min(report.min_area_ratio[t], static_cast<float>(ratio));
        });
        for (const glm::vec3& p : deformed.positions) {
            if (first) report.bounds = Bounds{p, p}, first = false;
            report.bounds.min = glm::min(report.bounds.min, p);
            report.bounds.max = glm::max(report.bounds.max, p);
        }
    }
    report.opened_triangles = static_cast<size_t>(std::count(opens.begin(), opens.end(), uint8_t(1)));
    report.opened = std::move(opens);
    if (triangles > 0) {
        report.max_ratio = *std::max_element(report.max_area_ratio.begin(), report.max_area_ratio.end());
        report.min_ratio = *std::min_element(report.min_area_ratio.begin(), report.min_area_ratio.end());
    }
    return report;
}

}  // namespace stipple::anim
