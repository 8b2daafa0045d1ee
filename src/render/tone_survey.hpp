#pragma once
// Does an object keep its tone as it moves away (§2.3, Figures 3-6)? The mean ink inside its footprint
// over a range of distances and views and, per frame, where the stipples the tone asks for go: each
// regime of the extrinsic enhancement (polygons large on screen, probabilistic selection, capped by their
// candidates and drawn with larger dots, culled), what it owes against what it draws, and how much ink the drawn stipples leave on
// the screen. Used by `stipple tone` and the tone tests.
#include <array>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "render/offscreen.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

enum class ToneRegime {
    Large,          // projected area >= min_area and room for a stipple: the s^pr rule, all of its owed stipples
    Probabilistic,  // projected area < min_area, or too little room for a whole stipple (polygon_density_terms):
                    // drawn with a probability, carrying the skipped ones' ink
    Enlarged,       // owed more than its candidates: draws all of them, larger (stipple_scale)
    Culled,         // faces away: owes nothing
    Outside,        // wholly outside the view (close up): owes the image nothing, and total() leaves it out
};
inline constexpr size_t kToneRegimeCount = 5;
const char* tone_regime_name(ToneRegime regime);

// Stipples, summed over a regime's polygons (fractional stipples count by their intensity).
struct RegimeTally {
    size_t polygons = 0;
    double owed = 0.0;      // what the tone asks for: the polygon's area x stipples per area x every term
    double allowed = 0.0;   // the same from its integer candidate count (what the formulas start from)
    double expected = 0.0;  // expected to draw: probability x the density it draws when selected
    double drawn = 0.0;     // drawn this frame (selection applied, and a flat polygon's last stipple solid or absent)
};

struct ToneTally {
    std::array<RegimeTally, kToneRegimeCount> regimes{};
    RegimeTally total() const;  // of the polygons in view (every regime but Outside)
};

// The regimes of one object this frame, from the CPU copy of its polygon constants and the uniforms
// StippleRenderer::prepare made (the formulas of shaders/stipple_formulas.h, as every path uses them).
ToneTally tally_tone(const ObjectGpu& object, const gpu::FrameUniforms& frame);

// What a rendered frame shows inside the object's footprint.
struct InkFigures {
    size_t covered = 0;  // pixels a surface covers
    double ink = 0.0;    // ink over them, in pixels (1 - luminance, summed)
    // The drawn stipples' ink if no two overlapped: each dot's visible pixels (covered, not hidden)
    // times its intensity, summed (only with the stipples' positions; see survey_tone).
    double unshared_ink = 0.0;
    // Where the rest of the dots' footprints went: pixels no surface covers (a dot spilling over the
    // outline) and pixels where a nearer surface hides it (or the depth test does), times intensity.
    double off_surface_ink = 0.0;
    double hidden_ink = 0.0;
    double hidden_whole_ink = 0.0;  // of hidden_ink: dots with no pixel left (a nearer part covers them)
    double mean() const { return covered ? ink / double(covered) : 0.0; }
};
// Over the covered pixels: how far each pixel's luminance (Rec. 709) has gone from the paper's toward the
// ink's, 1 - luminance for black ink on white paper (every figure of tone, tests and docs). Coloured paper
// and ink (a scene's) are read by their own luminances; where those are nearly the same there is no tone
// to read (ink_readable).
InkFigures measure_ink(const RenderedFrame& frame, glm::vec3 paper = glm::vec3(1.0f), glm::vec3 ink = glm::vec3(0.0f));
bool ink_readable(glm::vec3 paper, glm::vec3 ink);
// Rec. 709 luminance of a linear-looking RGB in [0, 1]: the one measure_ink and every colour check use.
double luminance(glm::vec3 rgb);

// Ink the frame's drawn stipples of `object` would leave if none overlapped another: each dot's pixels
// (the splat's square or disc) that a surface covers and that do not hide it, times its intensity.
// `positions` are the object's candidates in object space (StippleSet::positions).
// Fills `ink`'s unshared_ink, off_surface_ink and hidden_ink (adding to them).
void add_unshared_dot_ink(const ObjectGpu& object, const gpu::FrameUniforms& frame, const std::vector<glm::vec3>& positions,
                          const RenderedFrame& rendered, InkFigures& ink);

struct ToneSurveyOptions {
    VkExtent2D extent{1280, 1024};  // the image the object is framed in at distance 1
    std::vector<float> distances{1.0f, 2.0f, 4.0f, 8.0f, 16.0f};  // multiples of the framing distance
    std::vector<std::array<float, 2>> views{{30.0f, 10.0f}};      // yaw, pitch in degrees
    // Each view's figure is the mean over `frames` frames at yaws spread evenly over `arc_deg` around
    // it (the same yaws at every distance; 360 goes all around). A small object's tone rests on few
    // stipples: at 1/16 of a 1024-pixel frame about 150, and the selection is fixed per polygon (frame
    // coherence), so one view's tone is off by its own few percent at every nearby angle.
    int frames = 1;
    float arc_deg = 0.0f;
    bool regimes = false;  // also tally the regimes of every frame (tally_tone: a CPU pass over the polygons)
    // The camera's vertical field of view. Perspective changes what is seen as the object moves away
    // (at 30 degrees a framed sphere shows 75 degrees of its cap, at 16 times the distance nearly 90:
    // more of the side away from the light, less of the depth range near the centre); a narrow field
    // of view keeps the same surface in view at every distance, so what changes is only the scale.
    float fov_y_deg = OrbitCamera{}.fov_y_deg;
    // Parallel lines of sight instead (OrbitCamera::orthographic): the same surface in view at every distance
    // whatever the field of view, so that only the scale changes.
    bool orthographic = false;
    // When set, the first frame of each view and distance is written there as
    // tone-<yaw>_<pitch>-d<distance>-<on|off>.png (enlarged when the object is small).
    std::string image_dir;
};

struct ToneSample {
    float distance = 0.0f;
    std::vector<double> mean_ink;  // per view
    std::vector<ToneTally> tallies;  // per view, summed over its frames (empty regimes unless options.regimes)
    std::vector<InkFigures> ink;     // per view, summed over its frames
    // The object covers a pixel there and inks one: out of frame, or the camera inside it, not; nor where only
    // surfaces that draw no stipples are in view (the back of a one-sided open surface, which the depth pass
    // holds to hide what lies behind it; the camera inside an open mesh), whose ink 0 made max/min infinite.
    bool covered(size_t view) const;
};

struct ToneSurvey {
    std::vector<ToneSample> samples;  // one per distance
    // The largest mean ink over the smallest, over the distances where the object covers a pixel: NaN with
    // fewer than two such, infinite when one of them drew no ink. The worst is NaN if any view's is.
    double max_over_min(size_t view) const;
    double worst_max_over_min() const;
};

// Surveys of the same views and distances (say, one per seed) as one: each distance's ink in each view
// averaged over them, the tone under the noise of which stipples and polygons one seed draws. Its
// tallies and ink figures are the first survey's.
ToneSurvey mean_survey(const std::vector<ToneSurvey>& surveys);

// Renders object `object` of `renderer` (the only one it should hold) at every distance and view,
// framed on `bounds` in options.extent, with its current parameters; `light` is the view-space
// direction toward the light. Each frame is rendered only around the object: the same camera and
// pixel grid as the full image, cropped to the object's square (the tone is measured there alone).
// With `positions` (the object's StippleSet::positions) each frame's unshared ink is measured too.
ToneSurvey survey_tone(const gpu::Context& context, StippleRenderer& renderer, size_t object, const Sphere& bounds,
                       const ToneSurveyOptions& options, glm::vec3 light = FrameView{}.light_view,
                       const std::vector<glm::vec3>* positions = nullptr);

}  // namespace stipple
