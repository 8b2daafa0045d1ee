#include "render/tone_survey.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>

#include "anim/deform_cpu.hpp"
#include "core/error.hpp"
#include "render/deform_pass.hpp"
#include "render/density_formulas.hpp"
#include "render/polygon_constants.hpp"

namespace stipple {

const char* tone_regime_name(ToneRegime regime) {
    switch (regime) {
    case ToneRegime::Large: return "large";
    case ToneRegime::Probabilistic: return "probabilistic";
    case ToneRegime::Enlarged: return "enlarged";
    case ToneRegime::Culled: return "culled";
    case ToneRegime::Outside: return "outside the view";
    }
    return "?";
}

RegimeTally ToneTally::total() const {
    RegimeTally sum;
    for (size_t regime = 0; regime < kToneRegimeCount; ++regime) {
        if (ToneRegime(regime) == ToneRegime::Outside) continue;
        const RegimeTally& r = regimes[regime];
        sum.polygons += r.polygons;
        sum.owed += r.owed;
        sum.allowed += r.allowed;
        sum.expected += r.expected;
        sum.drawn += r.drawn;
    }
    return sum;
}

namespace {

// The shape the last frame drew: a static object's polygons and corners; an animated object's in the pose
// the renderer drew (the CPU reference deformation of that pose, anim/deform_cpu.hpp), each polygon due the
// share of its candidates the stretch rule gives it (stretched_due, as density.comp takes it). Until
// 2026-12-05 an animated object's regimes and dots were tallied on its rest shape, which its drawing does
// not have (the fox at 0 s of its first animation: 47% of its drawn dots "hidden" framed).
class DrawnShape {
public:
    explicit DrawnShape(const ObjectGpu& object) : object_(object) {
        if (!object.animation) return;
        const anim::Motion& motion = object.animation->motion;
        Mesh posed;
        posed.positions = anim::deform_cpu(*motion.model, object.animation->pose).positions;
        posed.indices = object.polygons.corner_indices;
        STIPPLE_CHECK(posed.positions.size() == object.polygons.corner_positions.size(), "the pose is not of this mesh");
        polygons_ = pack_polygon_constants(posed, std::vector<float>(posed.triangle_count(), 0.0f), object.polygons.box_min,
                                           object.polygons.box_size);
        for (size_t t = 0; t < polygons_.size(); ++t)  // the selection values (the high half) are the object's
            polygons_[t].center_z_selection =
                (polygons_[t].center_z_selection & 0xFFFFu) | (object.polygons.cpu[t].center_z_selection & 0xFFFF0000u);
        Mesh rest;
        rest.positions = object.polygons.corner_positions;
        rest.indices = object.polygons.corner_indices;
        full_areas_ = animated_full_areas(rest, motion);
        corners_ = std::move(posed.positions);
    }

    bool posed() const { return object_.animation != nullptr; }
    const std::vector<gpu::TriangleInfo>& polygons() const { return posed() ? polygons_ : object_.polygons.cpu; }
    const std::vector<glm::vec3>& corners() const { return posed() ? corners_ : object_.polygons.corner_positions; }
    // What the density takes for polygon t, with `candidates` of them: its view and the candidates due.
    formulas::PolygonView view(size_t t, float candidates) const {
        formulas::PolygonView view = formulas::polygon_view(polygons()[t], candidates, object_.frame.uniforms);
        if (posed()) view.due = formulas::stretched_due(candidates, polygons_[t].area, full_areas_[t]);
        return view;
    }
    // The rest area at which all of a polygon's candidates are due, summed: the area the candidates were made for.
    double full_area() const {
        double area = 0.0;
        if (posed())
            for (float a : full_areas_) area += a;
        else
            for (const gpu::TriangleInfo& info : object_.polygons.cpu) area += info.area;
        return area;
    }
    // Candidate k of polygon t (its rest position `rest`) where the drawn shape holds it: the same barycentric
    // coordinates in the posed triangle.
    glm::vec3 place(size_t t, const glm::vec3& rest) const {
        if (!posed()) return rest;
        const uint32_t* corner = &object_.polygons.corner_indices[3 * t];
        const std::vector<glm::vec3>& at_rest = object_.polygons.corner_positions;
        const glm::vec3 a = at_rest[corner[0]], e1 = at_rest[corner[1]] - a, e2 = at_rest[corner[2]] - a, d = rest - a;
        const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        const float det = d11 * d22 - d12 * d12;
        if (!(det > 0.0f)) return corners_[corner[0]];
        const float u = (d22 * glm::dot(d, e1) - d12 * glm::dot(d, e2)) / det;
        const float v = (d11 * glm::dot(d, e2) - d12 * glm::dot(d, e1)) / det;
        const glm::vec3 pa = corners_[corner[0]];
        return pa + u * (corners_[corner[1]] - pa) + v * (corners_[corner[2]] - pa);
    }

private:
    const ObjectGpu& object_;
    std::vector<gpu::TriangleInfo> polygons_;
    std::vector<glm::vec3> corners_;
    std::vector<float> full_areas_;
};

}  // namespace

ToneTally tally_tone(const ObjectGpu& object, const gpu::FrameUniforms& frame) {
    const formulas::DensityParams params = formulas::density_params(frame, object.frame.uniforms);
    const DrawnShape shape(object);
    const std::vector<gpu::TriangleInfo>& polygons = shape.polygons();
    // The stipples per unit area generation used (its total is within one stipple of it), so that a
    // polygon's owed ink follows its area, not its rounded candidate count; an animated object's per unit
    // of the area its candidates were made for (its rest area times its stretch headroom).
    const double area = shape.full_area();
    const double per_area = area > 0.0 ? double(object.geometry.stipple_count) / area : 0.0;

    // Close up most polygons may lie beyond the frame: the survey draws them (it keeps every polygon), but they
    // owe the image nothing, and counted with the rest they made "owed x point_size^2 / covered" read 4.98 for a
    // surface drawn at a quarter of its ink (the test of the density pass, as density.comp culls).
    const gpu::ObjectUniforms& uniforms = object.frame.uniforms;
    const glm::vec2 slack = formulas::view_cull_slack(glm::vec2(frame.viewport), uniforms.shading.y);
    const std::vector<glm::vec3>& corners = shape.corners();
    const std::vector<uint32_t>& indices = object.polygons.corner_indices;
    auto outside_view = [&](size_t t) {
        const glm::mat4& mvp = uniforms.model_view_proj;
        const uint32_t center_bits =
            formulas::clip_outside_bits(mvp * glm::vec4(formulas::polygon_center_object(polygons[t], uniforms), 1.0f), slack);
        return center_bits != 0u && formulas::triangle_outside_view(center_bits, mvp * glm::vec4(corners[indices[3 * t]], 1.0f),
                                                                      mvp * glm::vec4(corners[indices[3 * t + 1]], 1.0f),
                                                                      mvp * glm::vec4(corners[indices[3 * t + 2]], 1.0f), slack);
    };

    ToneTally tally;
    for (size_t t = 0; t < polygons.size(); ++t) {
        const float candidates = object.geometry.candidates(t);
        formulas::PolygonView view = shape.view(t, candidates);
        const formulas::PolygonDensity terms = formulas::polygon_density_terms(view, params);
        float drawn = formulas::polygon_density(view, params);
        // Drawn flat, its last stipple solid or absent as the density pass folds it (solid_dots_density); a polygon
        // large on screen decides each stipple where it lies, and its centroid's density stands for them here.
        if (!formulas::may_carry_gradient(terms, view, params, drawn))
            drawn = formulas::solid_dots_density(drawn, candidates, view.selection, params.flags);
        view.candidates = view.due = float(polygons[t].area * per_area);
        const formulas::PolygonDensity ideal = formulas::polygon_density_terms(view, params);

        const bool faces_away = formulas::polygon_faces_away(view.center, view.normal, params);
        ToneRegime regime = ToneRegime::Large;
        if (outside_view(t))
            regime = ToneRegime::Outside;
        else if (faces_away && (params.flags & gpu::kFlagTwoSided) == 0u)  // two-sided: seen from inside, it draws
            regime = ToneRegime::Culled;
        else if (ideal.owed > view.candidates)  // the model's regime, from the area (not the rounded count)
            regime = ToneRegime::Enlarged;
        else if (ideal.probability < 1.0f)
            regime = ToneRegime::Probabilistic;
        RegimeTally& r = tally.regimes[size_t(regime)];
        ++r.polygons;
        r.owed += ideal.owed;
        r.allowed += terms.owed;
        r.expected += double(terms.density) * terms.probability;
        r.drawn += drawn;
    }
    return tally;
}

double luminance(glm::vec3 rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

bool ink_readable(glm::vec3 paper, glm::vec3 ink) { return std::abs(luminance(paper) - luminance(ink)) >= 0.05; }

InkFigures measure_ink(const RenderedFrame& frame, glm::vec3 paper, glm::vec3 ink) {
    InkFigures f;
    // Luminance, Rec. 709 weights (the red channel alone read a red ink as light), from the paper's toward the
    // ink's: 1 - luminance for black on white. With a black paper and white ink it read the paper as 75% ink.
    // The colours as the 8-bit image holds them, so that bare paper reads 0 and solid ink 1.
    const auto stored = [](glm::vec3 c) { return glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f; };
    const double paper_l = luminance(stored(paper)), span = ink_readable(paper, ink) ? paper_l - luminance(stored(ink)) : 1.0;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        if (frame.depth[i] >= 1.0f) continue;
        ++f.covered;
        const uint8_t* rgb = &frame.color.pixels[4 * i];
        f.ink += (paper_l - luminance(glm::vec3(rgb[0], rgb[1], rgb[2]) / 255.0f)) / span;
    }
    return f;
}

void add_unshared_dot_ink(const ObjectGpu& object, const gpu::FrameUniforms& frame, const std::vector<glm::vec3>& positions,
                          const RenderedFrame& rendered, InkFigures& figures) {
    const formulas::DensityParams params = formulas::density_params(frame, object.frame.uniforms);
    const glm::mat4 model_view_proj = object.frame.uniforms.model_view_proj;
    const int width = int(frame.viewport.x), height = int(frame.viewport.y);
    const bool round = (object.frame.uniforms.flags.x & gpu::kFlagRoundPoints) != 0u;
    double ink = 0.0, off_surface = 0.0, hidden = 0.0, hidden_whole = 0.0;
    const DrawnShape shape(object);
    const std::vector<glm::vec3>& corners = shape.corners();
    for (size_t t = 0; t < shape.polygons().size(); ++t) {
        const formulas::PolygonView view = shape.view(t, object.geometry.candidates(t));
        const formulas::PolygonDensity terms = formulas::polygon_density_terms(view, params);
        float density = formulas::selected_density(terms, view.selection);
        const uint32_t candidates = object.geometry.first_stipple[t + 1] - object.geometry.first_stipple[t];
        // A large polygon's stipples, each at the density where it lies, as the shaders draw them.
        const uint32_t* corner = &object.polygons.corner_indices[3 * t];
        const glm::mat4& model_view = object.frame.uniforms.model_view;
        auto in_view = [&](const glm::vec3& p) { return glm::vec3(model_view * glm::vec4(p, 1.0f)); };
        glm::vec3 a(0.0f), b(0.0f), c(0.0f);
        glm::vec2 bounds(density);
        if (formulas::may_carry_gradient(terms, view, params, density)) {
            a = in_view(corners[corner[0]]), b = in_view(corners[corner[1]]), c = in_view(corners[corner[2]]);
            density = formulas::large_polygon_density(formulas::large_polygon_stored_density(terms, density), a, b, c, params);
            bounds = formulas::polygon_density_bounds(density, a, b, c, params);
        }
        if (bounds.x == bounds.y) {  // drawn flat: its last stipple solid or absent (solid_dots_density)
            density = formulas::solid_dots_density(density, float(candidates), view.selection, params.flags);
            bounds = glm::vec2(density);
        }
        // Where the density changes across the polygon: at each stipple whose index it decides, and at every
        // stipple where the candidates cannot carry it (its dot's size), as the shaders take it.
        const bool sizes_vary = bounds.x != bounds.y && bounds.y > float(candidates);
        for (uint32_t k = 0; k < formulas::drawn_stipple_count(bounds.y, candidates); ++k) {
            const glm::vec3 position = shape.place(t, positions[object.geometry.first_stipple[t] + k]);
            float here = density;
            if (sizes_vary || (bounds.x != bounds.y && float(k) + 1.0f > bounds.x && float(k) < bounds.y))
                here = formulas::stipple_density_here(density, in_view(position), a,
                                                      b, c, params);
            // A square dot enlarged beyond kRoundPointsAbovePx is a disc of its area (enlarged_square_extent).
            const float square_side = formulas::splat_dot_side(object.frame.uniforms.shading.y, here, float(candidates));
            const bool disc = formulas::drawn_dot_is_round(round, square_side);
            const float side = formulas::drawn_dot_extent(round, square_side);
            const float intensity = bounds.x != bounds.y ? formulas::drawn_intensity(here, float(k), view.selection, params.flags)
                                                         : formulas::stipple_intensity(here, float(k));
            if (intensity <= 0.0f) continue;
            const glm::vec4 clip = model_view_proj * glm::vec4(position, 1.0f);
            if (clip.w <= 0.0f) continue;
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            const glm::vec2 window(0.5f * (ndc.x + 1.0f) * float(width), 0.5f * (1.0f - ndc.y) * float(height));
            // The splat's pixels: centres inside the square (or the disc) of side `side`.
            const glm::ivec2 lo = glm::max(glm::ivec2(glm::ceil(window - 0.5f * side - 0.5f)), glm::ivec2(0));
            const glm::ivec2 hi = glm::min(glm::ivec2(glm::floor(window + 0.5f * side - 0.5f)), glm::ivec2(width - 1, height - 1));
            double dot_hidden = 0.0;
            bool dot_shows = false;
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const glm::vec2 d = (glm::vec2(x, y) + 0.5f - window) / side;
                    if (disc && glm::dot(d, d) > 0.25f) continue;
                    const float surface = rendered.depth[size_t(y) * size_t(width) + size_t(x)];
                    if (surface >= 1.0f)
                        off_surface += intensity;
                    else if (ndc.z > surface + 1e-6f)
                        dot_hidden += intensity;
                    else
                        ink += intensity, dot_shows = true;
                }
            hidden += dot_hidden;
            if (!dot_shows) hidden_whole += dot_hidden;
        }
    }
    figures.unshared_ink += ink;
    figures.off_surface_ink += off_surface;
    figures.hidden_ink += hidden;
    figures.hidden_whole_ink += hidden_whole;
}

namespace {

// The frame with each pixel repeated `zoom` times, so that a small object can be looked at.
Image enlarged(const Image& image, int zoom) {
    Image out;
    out.width = image.width * zoom;
    out.height = image.height * zoom;
    out.channels = image.channels;
    out.pixels.resize(size_t(out.width) * size_t(out.height) * size_t(out.channels));
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            for (int c = 0; c < out.channels; ++c)
                out.pixels[(size_t(y) * size_t(out.width) + size_t(x)) * size_t(out.channels) + size_t(c)] =
                    image.pixels[(size_t(y / zoom) * size_t(image.width) + size_t(x / zoom)) * size_t(image.channels) + size_t(c)];
    return out;
}

// The part of the full image (options.extent) that holds the object at `distance`: a square about its
// projected bounding sphere, even-sized so that it shares the full image's pixel grid.
VkExtent2D cropped_extent(VkExtent2D full, float distance) {
    const uint32_t side = 2u * uint32_t(std::ceil(0.5f * float(full.height) / std::max(distance, 1e-3f) + 4.0f));
    return {std::min(full.width, side), std::min(full.height, side)};
}

void add(RegimeTally& to, const RegimeTally& from) {
    to.polygons += from.polygons;
    to.owed += from.owed;
    to.allowed += from.allowed;
    to.expected += from.expected;
    to.drawn += from.drawn;
}

// The full image's camera at `distance`, seen through the `crop` window at its centre: the field of view
// narrowed by crop / full height, so pixels per unit (and with them every per-frame term) are the full
// image's.
FrameView survey_view(const Sphere& bounds, VkExtent2D full, VkExtent2D crop, float fov_y_deg, float distance, float yaw,
                      float pitch, glm::vec3 light, bool orthographic) {
    const float full_aspect = float(full.width) / float(full.height);
    // In parallel projection the span narrows with the field of view below as the perspective's does.
    OrbitCamera camera = frame_sphere(bounds, full_aspect, distance, yaw, pitch, fov_y_deg, orthographic);
    const float half = std::atan(std::tan(0.5f * glm::radians(fov_y_deg)) * float(crop.height) / float(full.height));
    camera.fov_y_deg = glm::degrees(2.0f * half);
    FrameView view;
    view.extent = crop;
    view.camera = camera_matrices(camera, float(crop.width) / float(crop.height), bounds);
    view.light_view = light;
    view.cull_outside_view = false;  // the drawn stipples are tallied against every polygon's owed ones
    return view;
}

}  // namespace

bool ToneSample::covered(size_t view) const { return view < ink.size() && ink[view].covered > 0 && ink[view].ink > 0.0; }

double ToneSurvey::max_over_min(size_t view) const {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    size_t counted = 0;
    for (const ToneSample& s : samples) {
        if (!s.covered(view)) continue;  // no tone where the object covers nothing
        const double ink = s.mean_ink.at(view);
        lo = std::min(lo, ink), hi = std::max(hi, ink), ++counted;
    }
    if (counted < 2 || hi == 0.0) return std::numeric_limits<double>::quiet_NaN();  // no ink anywhere: no ratio
    return lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
}

ToneSurvey mean_survey(const std::vector<ToneSurvey>& surveys) {
    STIPPLE_CHECK(!surveys.empty(), "mean_survey: no surveys");
    ToneSurvey mean = surveys.front();
    for (size_t i = 0; i < mean.samples.size(); ++i)
        for (size_t v = 0; v < mean.samples[i].mean_ink.size(); ++v) {
            double sum = 0.0;
            for (const ToneSurvey& s : surveys) sum += s.samples.at(i).mean_ink.at(v);
            mean.samples[i].mean_ink[v] = sum / double(surveys.size());
        }
    return mean;
}

double ToneSurvey::worst_max_over_min() const {
    double worst = 0.0;
    if (!samples.empty())
        for (size_t v = 0; v < samples[0].mean_ink.size(); ++v) {
            const double figure = max_over_min(v);
            if (std::isnan(figure)) return figure;
            worst = std::max(worst, figure);
        }
    return worst;
}

ToneSurvey survey_tone(const gpu::Context& context, StippleRenderer& renderer, size_t object, const Sphere& bounds,
                       const ToneSurveyOptions& options, glm::vec3 light, const std::vector<glm::vec3>* positions) {
    ToneSurvey survey;
    for (float distance : options.distances) {
        ToneSample sample;
        sample.distance = distance;
        const VkExtent2D crop = cropped_extent(options.extent, distance);
        OffscreenTarget target(context, crop);
        const int frames = std::max(options.frames, 1);
        for (const auto& [yaw, pitch] : options.views) {
            ToneTally tally;
            InkFigures ink;
            for (int j = 0; j < frames; ++j) {
                const float offset = options.arc_deg * ((float(j) + 0.5f) / float(frames) - 0.5f);
                RenderedFrame frame = target.render(
                    renderer, survey_view(bounds, options.extent, crop, options.fov_y_deg, distance, yaw + offset, pitch, light,
                                         options.orthographic));
                if (options.regimes) {
                    const ToneTally one = tally_tone(renderer.object(object), renderer.frame_uniforms());
                    for (size_t r = 0; r < kToneRegimeCount; ++r) add(tally.regimes[r], one.regimes[r]);
                }
                if (j == 0 && !options.image_dir.empty()) {
                    // The distance as typed (0.4, not the float's 0.400000006), unless 6 digits would not tell
                    // it from its neighbours.
                    char shown[32];
                    std::snprintf(shown, sizeof shown, "%g", double(distance));
                    if (std::strtof(shown, nullptr) != distance) std::snprintf(shown, sizeof shown, "%.9g", double(distance));
                    char name[160];
                    std::snprintf(name, sizeof name, "/tone-%g_%g-d%s-%s.png", yaw, pitch, shown,
                                  renderer.params(object).extrinsic ? "on" : "off");
                    write_png(options.image_dir + name, enlarged(frame.color, std::clamp(int(256 / crop.height), 1, 8)));
                }
                const InkFigures f = measure_ink(frame);
                ink.covered += f.covered;
                ink.ink += f.ink;
                if (positions)
                    add_unshared_dot_ink(renderer.object(object), renderer.frame_uniforms(), *positions, frame, ink);
            }
            sample.mean_ink.push_back(ink.mean());
            sample.tallies.push_back(tally);
            sample.ink.push_back(ink);
        }
        survey.samples.push_back(std::move(sample));
    }
    return survey;
}

}  // namespace stipple
