// The paper's per-frame density formulas, in exactly one place: the GLSL shaders include this file,
// and the C++ CPU path includes it through src/render/density_formulas.hpp (glm supplies the same
// functions). Every literal carries an f suffix and every integer is 32-bit unsigned, so both
// languages compute the same values. docs/paper-reading.md explains each reading of the paper.
#ifndef STIPPLE_FORMULAS_H
#define STIPPLE_FORMULAS_H

#ifdef __cplusplus
#define STIPPLE_FN inline
#else
#define STIPPLE_FN
#endif

STIPPLE_CONST float kPi = 3.14159265358979f;

// §2.2 Shading. The paper shades with the Lambertian term (N.L)^n; stipples convey darkness, so the
// share of a polygon's candidates drawn is 1 - (N.L)^n: a surface facing the light is left white, one
// facing away gets every candidate. n > 0 (n > 1 widens the dark tones, n < 1 the light ones).
STIPPLE_FN float shading_fraction(vec3 unit_normal, vec3 unit_to_light, float exponent) {
    float lambert = dot(unit_normal, unit_to_light);
    if (lambert <= 0.0f) return 1.0f;
    // Near the highlight 1 - lambert^n cancels; there we use 1 - lambert = |N x L|^2 / (1 + lambert) and
    // 1 - (1 - x)^n = -expm1(n log1p(-x)) by short series, so the CPU and the GPU agree to 1e-6 even
    // where the drawn share is tiny.
    vec3 c = cross(unit_normal, unit_to_light);
    float x = dot(c, c) / (1.0f + lambert);
    if (x > 0.01f) return 1.0f - pow(lambert, exponent);
    float y = -exponent * x * (1.0f + x * (0.5f + x * (1.0f / 3.0f + 0.25f * x)));  // n log1p(-x)
    if (y < -0.05f) return 1.0f - exp(y);
    return -y * (1.0f + y * (0.5f + y * (1.0f / 6.0f + y * (1.0f / 24.0f))));       // -expm1(y)
}

// §2.1/§2.3 The orientation term of the projected area, "cos(N_z * pi)" with N_z the z component of the
// image-space normal. Taken literally it is negative for N_z > 1/2. The paper calls the product "the
// approximated projected screen area", so we read the term as the projected area's own factor: N_z, measured
// against the eye ray (perspective-correct facing ratio). Until 2026-12-06 we read it as the ramp
// (1 - cos(pi N_z)) / 2 = sin^2(pi N_z / 2), which is 0 edge-on and 1 facing like N_z but falls below it
// toward the outline (0.60 N_z at 75 degrees): an unlit plate read 0.548 facing and 0.334 at 75 degrees, and
// where one part passes in front of another a light band 4-6 px wide ran along its outline (two spheres, the
// bunny's back against its head). With N_z the plate reads 0.544 facing, 0.498 at 75 degrees and 0.454 at 85
// (what its foreshortened dots lose to overlap), and the band is gone.
STIPPLE_FN float orientation_factor(float facing) {
    return clamp(facing, 0.0f, 1.0f);
}

// §2.3 Extrinsic distance enhancement, polygons large enough on screen:
// density / ((Z_min - Z_curr) / 2)^pr. We read the bracket as the polygon's distance relative to the
// reference distance (where the object is framed in the reference view that set its candidate counts,
// see src/stipple/generate.cpp), i.e. the inverse of its current linear screen scale s. So the factor
// is s^pr: pr = 2 keeps the stipples per screen pixel constant (the projected area shrinks as s^2).
STIPPLE_FN float extrinsic_factor(float screen_scale, float pr) {
    return pow(max(screen_scale, 0.0f), pr);
}

// §2.3 Intrinsic depth enhancement: density * (1 + (Z_curr / A)^de) with Z_curr the polygon's depth in
// the object's depth range (-A, A). We measure Z_curr toward the viewer from the object's centre (so
// near parts are positive) and keep the sign for real exponents: 1 + sign(z) |z|^de, from 0 at the far
// end through 1 at the centre to 2 at the near end (then capped by the candidates). Larger de
// lessens the effect, smaller de exaggerates it.
STIPPLE_FN float intrinsic_factor(float depth_toward_viewer, float half_range, float de) {
    float z = clamp(depth_toward_viewer / max(half_range, 1e-20f), -1.0f, 1.0f);
    return 1.0f + sign(z) * pow(abs(z), de);
}

// §3.1 Toon silhouettes. The paper multiplies N.E by an increasing ramp clamped to [0, 1] and uses the
// result as the surface's intensity, so that only surfaces seen edge-on darken; the ramp's steepness
// sets the sharpness. Our reading, as ink: clamp(1 - k N.E, 0, 1) — full ink edge-on, none once
// N.E > 1/k. The stipples get the matching decreasing ramp, clamp(k N.E, 0, 1), so they fade where the
// toon ink takes over. N.E is measured against the eye ray.
STIPPLE_FN float toon_surface_ink(float n_dot_e, float sharpness) {
    return clamp(1.0f - sharpness * n_dot_e, 0.0f, 1.0f);
}

STIPPLE_FN float toon_stipple_fade(float n_dot_e, float sharpness) {
    return clamp(sharpness * n_dot_e, 0.0f, 1.0f);
}

// §3.1 Raskar-Cohen line thinning: the bounding-sphere radius perpendicular to the view is projected to
// the screen; its size relative to the object's line reference size scales the user's width, clamped
// between one pixel and that width. The line reference is the object framed in the default
// 1280x1024 image (radius 512 px): the width the user sets is the width seen there. It is deliberately
// not the generation's reference view (kReferenceHeight, radius 640 px), which is 25% closer so that the
// near side of a framed object finds enough candidates (src/stipple/stipple_set.hpp).
STIPPLE_CONST float kLineReferenceRadiusPx = 512.0f;

STIPPLE_FN float silhouette_line_width(float user_width, float projected_radius_px, bool thinning) {
    if (!thinning) return user_width;
    return clamp(user_width * projected_radius_px / kLineReferenceRadiusPx, 1.0f, user_width);
}

// Which lines an edge of the mesh carries this frame, from whether the polygons on either side face
// away (a border edge has no second polygon: `has_second` false) and the cosine of its dihedral angle.
// Raskar-Cohen (§3.1) draws the back faces' edges and lets the front faces' depth keep the silhouette;
// of those edges we keep the ones that can be a silhouette: one side faces away and the other does not
// or is missing. An edge between two back faces passes the depth test only within a line width of a
// contour, which its own wide line covers (on a closed mesh every back face lies behind the front
// surface), so little is lost; and on an open mesh those are the edges that inked the back faces
// seen through an opening as a solid patch.
STIPPLE_FN bool raskar_cohen_edge(bool first_away, bool has_second, bool second_away) {
    return first_away != (has_second && second_away);
}

STIPPLE_FN bool contour_edge(bool first_away, bool has_second, bool second_away) {
    return has_second && first_away != second_away;
}

// A crease: the polygons' unit normals make an angle above the crease angle (its cosine given).
STIPPLE_FN bool crease_edge(bool has_second, vec3 first_normal, vec3 second_normal, float cos_crease_angle) {
    return has_second && dot(first_normal, second_normal) < cos_crease_angle;
}

// §2.1 No popping: a polygon with fractional density d draws stipples 0..ceil(d)-1, the last one
// with intensity frac(d). Index k (0-based) is drawn with intensity clamp(d - k, 0, 1); zero means
// the stipple is culled (pushed beyond the far plane by the vertex shader, §3.2).
STIPPLE_FN float stipple_intensity(float density, float index) {
    return clamp(density - index, 0.0f, 1.0f);
}

// Beyond the paper (kFlagSolidDots, the default; ObjectParams::faint_dots off): the last stipple drawn solid
// or not at all. §2.1's fraction draws it at the fraction's intensity; where polygons hold about one stipple
// each (a fine mesh framed, any lit surface at a low D_max) every dot is such a last one, and the drawing is a
// grey wash where an illustrator draws sparse black dots; moving the object a little farther turned the same
// surface into black dots (probabilistic selection, §2.3), a change of look within a 25% zoom (a review,
// 2026-12-06: 59% of the inked pixels of the bunny framed at 512 x 512 grey, 7% at 1.15 times the distance).
// Instead the fraction f is compared with a threshold u of the polygon's own (its fixed selection value of
// §2.3, uniform in (0, 1) and spread evenly over the surface by its ranking): the dot is solid where f is
// above u and absent below, so the expected ink is f, as the paper's, and the polygons that show their last
// dot at a fraction f are those with u < f, spread as probabilistic selection spreads them. Within
// kSolidDotBand of u the dot fades (a ramp of that width centred on f = u, narrowed near f = 0 and 1 so that
// it stays inside (0, 1) and the mean stays f exactly): a density that moves slowly never pops a dot, it
// fades in over a tenth of a stipple's worth of density instead of a whole one. (A band of 0.25 left 22% of
// the framed bunny's inked pixels grey, 0.1 leaves 11%, the faint dots of the paper's rule 67%; the same mean
// ink, 24.0%, in all three.)
STIPPLE_CONST float kSolidDotBand = 0.1f;

STIPPLE_FN float solid_dot_intensity(float fraction, float threshold) {
    if (fraction >= 1.0f) return 1.0f;
    if (!(fraction > 0.0f)) return 0.0f;
    float band = min(kSolidDotBand, 2.0f * min(fraction, 1.0f - fraction));
    return clamp((fraction - threshold) / band + 0.5f, 0.0f, 1.0f);
}

// A stipple's intensity with its polygon's threshold, by the object's rule (stipple_intensity, or solid dots).
STIPPLE_FN float drawn_intensity(float density, float index, float threshold, uint flags) {
    float fraction = stipple_intensity(density, index);
    return (flags & kFlagSolidDots) != 0u ? solid_dot_intensity(fraction, threshold) : fraction;
}

// The density a polygon drawn flat (its density the same over it) carries with solid dots: its whole stipples
// and its last one's intensity, which stipple_intensity then reads back (so every drawing path follows
// without a change). Not where the candidates cannot carry the density (all drawn, enlarged: no last one).
STIPPLE_FN float solid_dots_density(float density, float candidates, float threshold, uint flags) {
    if ((flags & kFlagSolidDots) == 0u || !(density < candidates) || !(density > 0.0f)) return density;
    float whole = floor(density);
    return whole + solid_dot_intensity(density - whole, threshold);
}

// Beyond the paper, for round dots (points above 2.5 px, kFlagRoundPoints, and every dot of a print): the
// last stipple's fraction f of a dot of side s is drawn as a smaller dot of full ink, of side s sqrt(f).
// Its area, so its ink, is the faded dot's, and it grows as f does: still no popping. Vector output draws
// it so (plot_plan: radius times sqrt(intensity)), and a pen has no grey: a faint disc many pixels wide
// reads as a wash, not as a dot. Down to a pixel a small black dot still inks its area on average (pixel
// centres sample a disc without bias: a 1.8-px dot inks 2-4 pixels, 2.5 on average); below
// kShrunkDotMinSide it keeps that side and fades instead (intensity f s^2 / side^2, the same ink). Until
// 2026-11-27 the floor was 2.5 px: on a fine mesh at low density most dots are fractions under it, and
// 4-px dots read as a grey wash with a few black dots (mean ink within 1% of today's). The paper's 1-2 px
// points fade (stipple_intensity). Returns (side, intensity).
STIPPLE_CONST float kShrunkDotMinSide = 1.0f;

STIPPLE_FN vec2 fractional_round_dot(float fraction, float side) {
    float shrunk = side * sqrt(fraction);
    if (shrunk >= kShrunkDotMinSide) return vec2(shrunk, 1.0f);
    float kept = min(side, kShrunkDotMinSide);
    return vec2(kept, clamp(fraction * (side * side) / (kept * kept), 0.0f, 1.0f));
}

// A polygon owed more stipples than it has candidates (close up, on a large image, or near and dark
// with the intrinsic enhancement) draws all of them, each dot enlarged so that the ink is the owed
// ink: its side grows by sqrt(density / candidates), at most kMaxStippleScale (beyond that the
// surface would be drawn with blots, and the tone is let go). The density a polygon carries may
// therefore exceed its candidates; these two functions are how every drawing path reads it.
STIPPLE_CONST float kMaxStippleScale = 4.0f;
// The most density any stipple is given (large_polygon_density, stipple_density_here): far beyond any
// polygon's candidates, far below the float range.
STIPPLE_CONST float kMostDensity = 1.0e30f;

STIPPLE_FN uint drawn_stipple_count(float density, uint candidates) {
    // Compared as floats first: a large polygon close up may carry a density beyond any uint.
    return density >= float(candidates) ? candidates : min(uint(ceil(max(density, 0.0f))), candidates);
}

STIPPLE_FN float stipple_scale(float density, float candidates) {
    return clamp(sqrt(density / max(candidates, 1.0f)), 1.0f, kMaxStippleScale);
}

// §2.1 hidden-stipple removal for dots larger than the depth pass's polygon offset was set for. A dot is
// drawn flat, at its centre's depth, while its polygon's depth changes across it: on a slanted face half
// of a 32-px disc fell behind its own surface (cut circles). Its depth is pulled toward the eye by what its
// plane changes over half its side, less what the polygon offset already gives (kDepthBiasSlopeFactor times
// the larger slope): nothing for dots up to 1.5 px, so the default look keeps the paper's plain test.
// depth_slope: the polygon's window depth change per pixel along x and y (window_depth_slope).
STIPPLE_FN float large_dot_depth_pull(vec2 depth_slope, float side) {
    float across = 0.5f * side * (abs(depth_slope.x) + abs(depth_slope.y));
    return max(across - kDepthBiasSlopeFactor * max(abs(depth_slope.x), abs(depth_slope.y)), 0.0f);
}

// Beyond the paper: a square dot (points of kRoundPointsAbovePx and below) enlarged beyond that size where the
// candidates cannot carry the density (stipple_scale) is drawn as a disc of the same area, as round points
// are (close up the 6-px squares of a coarse mesh read as blocks, until 2026-12-05). Its diameter, or the
// side itself where it stays square; enlarged_square_is_round says which.
STIPPLE_CONST float kSquareToDiscDiameter = 1.1283792f;  // 2 / sqrt(pi): a disc of this diameter inks side^2
STIPPLE_FN bool enlarged_square_is_round(float side) { return side > kRoundPointsAbovePx; }
STIPPLE_FN float enlarged_square_extent(float side) {
    return enlarged_square_is_round(side) ? side * kSquareToDiscDiameter : side;
}
// A dot of side `side` as drawn: a disc where the object draws round points (`round_points`) or the square
// is enlarged into one, and the width of the box it covers.
STIPPLE_FN bool drawn_dot_is_round(bool round_points, float side) { return round_points || enlarged_square_is_round(side); }
STIPPLE_FN float drawn_dot_extent(bool round_points, float side) { return round_points ? side : enlarged_square_extent(side); }

// The side of a polygon's dots on the splat, in pixels: the point size, larger where the candidates cannot
// carry the density (stipple_scale), and at most kSplatMaxSide (shared_types.h).
STIPPLE_FN float splat_dot_side(float point_size, float density, float candidates) {
    return min(point_size * stipple_scale(density, candidates), kSplatMaxSide);
}

// The iterations of a dot's box of pixel centres (at most ceil(side) + 1 a side), and at most how many
// its search for pixels to move into may take (kSplatRingFactor, kSplatRingCap in shared_types.h).
STIPPLE_FN uint splat_box_iterations(float side) {
    uint n = uint(ceil(side)) + 1u;
    return n * n;
}
STIPPLE_FN uint splat_ring_budget(float side) { return min(kSplatRingFactor * splat_box_iterations(side), kSplatRingCap); }

// The splat's work items: a polygon drawing `drawn` stipples of side `side` is cut into runs of this many
// (kSplatShortRun, kSplatChunk and kSplatIterationBudget in shared_types.h say why). The density pass,
// the CPU's list and the splat all cut alike. A square dot enlarged into a disc covers a box of its
// diameter (enlarged_square_extent), which the object's point size says: round points are drawn at
// their side.
STIPPLE_FN uint splat_run_length(uint drawn, float side, float point_size) {
    uint longest = drawn <= kSplatChunk ? kSplatShortRun : kSplatChunk;
    float extent = drawn_dot_extent(point_size > kRoundPointsAbovePx, side);
    uint per_dot = splat_box_iterations(extent) + splat_ring_budget(extent);
    return clamp(kSplatIterationBudget / per_dot, kSplatShortRun, longest);
}

// Everything one polygon's density depends on, in view space.
struct PolygonView {
    float candidates;     // N_max of the polygon (its stipple count): no more can be drawn
    float due;            // the candidates due at its current shape: all of them, or fewer for a polygon
                          // generated with stretch headroom (stretched_due)
    float selection;      // fixed selection value in [0, 1) (src/stipple/selection_order.cpp)
    float area;           // world-space area
    float scale_ratio;    // its linear scale from object to world over the object's mean (1 but for an
                          // unequal scale of the axes)
    vec3 center;          // view-space centroid (the eye at the origin looking down -z)
    vec3 normal;          // view-space unit normal
};

struct DensityParams {
    vec3 to_light;             // view-space unit direction toward the light
    float shading_exponent;    // n
    float toon_sharpness;      // k of the toon ramps
    float pr;                  // extrinsic rate
    float min_area;            // minimum stipple screen area, px^2 (2..9 in the paper)
    float pixels_per_unit;     // pixels per world unit at unit distance (projection and viewport)
    float reference_ppu;       // pixels per world unit in the object's reference view
    float de;                  // intrinsic rate
    float half_range;          // A: the object's depth half-range (bounding-sphere radius)
    float center_depth;        // view distance of the object's centre
    float near_plane;          // view distance of the near plane: nearer points are never drawn
    float near_margin;         // how far a quantised centroid may lie from the true one, in view depth
    uint flags;                // kFlag* bits
    float orthographic;        // 1: parallel lines of sight (FrameUniforms::projection.z), 0: perspective
};

// Beyond the paper, which draws in perspective: an orthographic view (technical and scientific illustration).
// Every line of sight is parallel, so the eye ray is +z (toward the viewer) at every point, and a point's
// size on screen does not depend on its depth: pixels_per_unit is then the scale at every depth, and the
// distance that divides it is 1. The depth itself (the intrinsic enhancement, the near plane) stays the
// view depth. With these two, every formula below reads the same in both projections.
STIPPLE_FN vec3 toward_eye(vec3 x, DensityParams q) {
    return q.orthographic != 0.0f ? vec3(0.0f, 0.0f, 1.0f) : -x;  // not normalised
}
STIPPLE_FN float scaling_distance(float depth, DensityParams q) {
    return q.orthographic != 0.0f ? 1.0f : depth;
}
// The facing ratio N.E of unit normal `normal` at view-space point x (the eye ray normalised).
STIPPLE_FN float facing_ratio(vec3 normal, vec3 x, DensityParams q) {
    vec3 e = toward_eye(x, q);
    return dot(normal, e) / max(length(e), 1e-20f);
}

// The inverse of octahedral_to_unit: the unit sphere onto the octahedron, the lower half folded out.
STIPPLE_FN vec2 unit_to_octahedral(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = vec2(n.x, n.y);
    if (n.z < 0.0f) {
        vec2 side = vec2(p.x >= 0.0f ? 1.0f : -1.0f, p.y >= 0.0f ? 1.0f : -1.0f);
        p = (vec2(1.0f) - abs(vec2(p.y, p.x))) * side;
    }
    return p;
}

// Density follows stretch (animated objects): a polygon's candidates were generated for `full_area`,
// its rest area times its headroom, so at its current `area` (both object space) it is due that share
// of them. A polygon at twice its rest area is due twice its rest count (while the candidates last); a
// shrunk one fewer, so the tone stays even on the moving surface.
STIPPLE_FN float stretched_due(float candidates, float area, float full_area) {
    return full_area > 0.0f ? candidates * (area / full_area) : 0.0f;
}

// A unit vector from its octahedral encoding in [-1, 1]^2 (the lower hemisphere folded outward).
STIPPLE_FN vec3 octahedral_to_unit(vec2 e) {
    vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    float fold = max(-v.z, 0.0f);
    v.x += v.x >= 0.0f ? -fold : fold;
    v.y += v.y >= 0.0f ? -fold : fold;
    return normalize(v);
}

// A 32-bit integer hash (lowbias32): the same bits in C++ and GLSL.
STIPPLE_FN uint hash_uint(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// The polygon's fixed selection value (§2.3) in (0, 1): its 16-bit step, and a place inside the step
// from a hash of its other constants (8 more bits). Far away on a fine mesh a polygon's probability is
// a few steps or less; compared with the step alone, every polygon of a region would round alike (to
// nothing, below half a step). With the hash the values are uniform within the step, so the share
// selected stays the probability down to 2^-24. The last place of the last step rounds to 1 in float: it is
// kept below (the largest float under 1), which no probability under 1 tells apart, so that the value stays
// in (0, 1) (the triangles without a candidate all hold the last step; selection_order.cpp).
STIPPLE_FN float polygon_selection(TriangleInfo info) {
    uint within = hash_uint(info.center_xy ^ hash_uint(info.normal ^ (info.center_z_selection << 16u))) >> 24u;
    return min((float(((info.center_z_selection >> 16u) << 8u) | within) + 0.5f) * (1.0f / 16777216.0f), 0.99999994f);
}

// The polygon's centroid in object space, as TriangleInfo quantises it in the object's box.
STIPPLE_FN vec3 polygon_center_object(TriangleInfo info, ObjectUniforms o) {
    vec2 xy = unpackUnorm2x16(info.center_xy);
    float z = unpackUnorm2x16(info.center_z_selection).x;
    return vec3(o.box_min) + vec3(o.box_size) * vec3(xy.x, xy.y, z);
}

// Beyond the paper: a polygon wholly outside the view draws nothing (kFlagCullOutsideView). The paper's
// density is the same wherever a polygon lies on screen, so close up the polygons beyond the frame's
// edges, and those behind the eye, kept their stipples, and each was placed, clipped and thrown away (the
// bunny at a third of its framing distance drew 139,567 stipples for 16,862 in the image; with the
// camera inside it, 37,656 for none). Tested in clip space, so that a tile's off-centre projection is
// culled to its own viewport: a point's bits name the planes it lies beyond (right, left, top, bottom,
// nearer than the near plane, beyond the far one), the sides widened by the farthest a dot of the object
// reaches past its centre (view_cull_slack); a triangle is outside when its three corners lie beyond one
// plane. The images are the same: only stipples no pixel shows are dropped.
STIPPLE_CONST float kCullGuardPx = 4.0f;  // beyond the largest dot's half side: rounding, the splat's ring
STIPPLE_FN uint clip_outside_bits(vec4 p, vec2 slack) {
    uint bits = 0u;
    if (p.x > p.w * slack.x) bits |= 1u;
    if (p.x < -p.w * slack.x) bits |= 2u;
    if (p.y > p.w * slack.y) bits |= 4u;
    if (p.y < -p.w * slack.y) bits |= 8u;
    if (p.z < 0.0f) bits |= 16u;
    if (p.z > p.w) bits |= 32u;
    return bits;
}
// Whether a triangle lies wholly outside the view: its clip-space corners all beyond one plane (and its
// centroid, whose bits `center_bits` say whether the corners need reading at all: 0, inside).
STIPPLE_FN bool triangle_outside_view(uint center_bits, vec4 a, vec4 b, vec4 c, vec2 slack) {
    return (center_bits & clip_outside_bits(a, slack) & clip_outside_bits(b, slack) & clip_outside_bits(c, slack)) != 0u;
}
// The clip-space widening of the frame's sides: 1 + the reach of the object's largest dot (its point size
// enlarged by kMaxStippleScale, and a square then drawn as a disc of its area) over half the viewport.
STIPPLE_FN vec2 view_cull_slack(vec2 viewport, float point_size) {
    float reach = 0.5f * point_size * kMaxStippleScale * kSquareToDiscDiameter + kCullGuardPx;
    return vec2(1.0f) + 2.0f * reach / viewport;
}

// The density inputs of one polygon, from its constant data, its candidate count and the object's uniforms.
STIPPLE_FN PolygonView polygon_view(TriangleInfo info, float candidates, ObjectUniforms o) {
    PolygonView p;
    p.candidates = candidates;
    p.due = candidates;
    p.selection = polygon_selection(info);
    p.area = info.area * o.extrinsic.w;
    p.scale_ratio = 1.0f;
    p.center = vec3(o.model_view * vec4(polygon_center_object(info, o), 1.0f));
    vec3 normal = mat3(o.normal_view) * octahedral_to_unit(unpackSnorm2x16(info.normal));
    p.normal = normalize(normal);
    // A model matrix M that scales its axes unequally scales a polygon's area by |det M| |M^-T n| (n its
    // unit normal), which depends on how the polygon lies: against the mean scale s = |det M|^(1/3) of
    // extrinsic.w = s^2 that is s |M^-T n|, the length of the unnormalised view normal (normal_view is
    // M's inverse transpose; the view turns it without scaling) times s. Taken as s^2 for every polygon,
    // a plate squashed 3x across its plane drew 1.5 times the stipples of the same plate stored squashed,
    // one stretched 3x along it 0.69 times. A similarity keeps 1 exactly (o.intrinsic.w = 0).
    if (o.intrinsic.w != 0.0f) {
        float area_ratio = length(normal) * sqrt(o.extrinsic.w);
        p.area *= area_ratio;
        p.scale_ratio = sqrt(area_ratio);
    }
    return p;
}

STIPPLE_FN DensityParams density_params(FrameUniforms f, ObjectUniforms o) {
    DensityParams q;
    q.to_light = vec3(f.light_view);
    q.shading_exponent = o.shading.x;
    q.toon_sharpness = o.shading.z;
    q.pr = o.extrinsic.x;
    q.min_area = o.extrinsic.y;
    q.pixels_per_unit = f.projection.x;
    q.reference_ppu = o.extrinsic.z;
    q.de = o.intrinsic.x;
    q.half_range = o.intrinsic.y;
    q.center_depth = o.intrinsic.z;
    q.near_plane = f.projection.y;
    q.near_margin = o.box_size.w;
    q.flags = o.flags.x;
    q.orthographic = f.projection.z;
    return q;
}

// §3.1 Whether a polygon faces away from the viewer (its stipples are culled unless two-sided; an edge
// between one that does and one that does not is a contour): N.E <= 0 against the eye ray to its
// centroid, the test polygon_density_terms uses. The density pass records it per polygon (one bit).
STIPPLE_FN bool polygon_faces_away(vec3 view_center, vec3 view_normal, DensityParams q) {
    return dot(view_normal, toward_eye(view_center, q)) <= 0.0f;
}

// One polygon's density this frame, before the selection draw: the density it draws if selected and
// the probability that it is selected (1 outside the probabilistic regime).
struct PolygonDensity {
    float density;
    float probability;
    float owed;         // every term applied, before the candidates cap: the stipples the tone asks for
    float screen_area;  // approximate projected area in px^2 (0 without the extrinsic enhancement)
    float unplaced;     // a centroid nearer than the near plane: the density without the terms that depend on
                        // where a point lies (large_polygon_density takes them elsewhere); else 0
};

// The D_max for which min_area is given (the default): a polygon of min_area px^2 then holds min_area x this
// many stipples where fully dark, and one whole stipple at the default min_area of 4 px^2.
STIPPLE_CONST float kMinAreaDensity = 0.25f;

// §2.1-2.3: shading, intrinsic and extrinsic enhancement, in both regimes; density in stipples (above the
// candidates when they cannot carry it: stipple_scale).
STIPPLE_FN PolygonDensity polygon_density_terms(PolygonView p, DensityParams q) {
    PolygonDensity result;
    result.density = 0.0f;
    result.probability = 1.0f;
    result.owed = 0.0f;
    result.screen_area = 0.0f;
    result.unplaced = 0.0f;
    if (p.candidates <= 0.0f || p.due <= 0.0f) return result;
    float distance = -p.center.z;
    // Which side of its plane the eye is on: the same seen from any point of the plane, so known even where
    // the centroid lies behind the eye.
    float side = dot(p.normal, toward_eye(p.center, q));
    // Two-sided: a polygon facing away is seen from its inside (through an opening), so it takes the
    // outside's tone rule with its normal flipped (shading, orientation, toon fade).
    if ((q.flags & kFlagTwoSided) != 0u && side < 0.0f) {
        p.normal = -p.normal;
        side = -side;
    }
    if ((q.flags & kFlagBackfaceCull) != 0u && side <= 0.0f) return result;
    float facing = side / max(length(toward_eye(p.center, q)), 1e-20f);

    float density = p.due;
    if ((q.flags & kFlagShading) != 0u) density *= shading_fraction(p.normal, q.to_light, q.shading_exponent);
    // A centroid nearer than the near plane (or within the centroids' quantisation of it: near_margin) is no
    // place to take the terms that depend on where a point lies; the polygon is large on screen, and its
    // gradient pass takes them at its reference point (large_polygon_density). Of the extrinsic term only the
    // polygon's own scale is kept (one pow for both cases: lavapipe computes both under its mask).
    bool unplaced = distance < q.near_plane + q.near_margin;
    float screen_scale =
        unplaced ? p.scale_ratio : p.scale_ratio * q.pixels_per_unit / (scaling_distance(distance, q) * q.reference_ppu);
    float extrinsic = extrinsic_factor(screen_scale, q.pr);
    if (unplaced) {
        result.unplaced = (q.flags & kFlagExtrinsic) != 0u ? density * extrinsic : density;
        return result;
    }
    if ((q.flags & kFlagIntrinsic) != 0u) density *= intrinsic_factor(q.center_depth - distance, q.half_range, q.de);
    if ((q.flags & kFlagToonFade) != 0u) density *= toon_stipple_fade(facing, q.toon_sharpness);
    if ((q.flags & kFlagExtrinsic) == 0u) {
        result.owed = density;
        result.density = min(density, p.candidates * kMaxStippleScale * kMaxStippleScale);
        return result;
    }
    float orientation = orientation_factor(facing);
    result.owed = density * extrinsic * orientation;
    // Not capped at the candidates: a polygon owed more draws all of them, larger (stipple_scale).
    density = min(result.owed, p.candidates * kMaxStippleScale * kMaxStippleScale);
    result.density = density;

    // §2.3 Polygons smaller on screen than the minimum stipple area: probabilistic selection. The paper
    // draws such a polygon with probability p = area / min_area, carrying the ink of the ones skipped
    // (density / p). Our reading keeps the expected ink (p x density / p = the density) and chooses p
    // for the ink on screen: a selected polygon draws exactly one whole stipple, p = density. Carrying
    // more (the paper's p when density > area / min_area) stacks several dots inside a polygon smaller
    // than a dot, where they overlap and read lighter than the same dots spread out; a fraction of one
    // is what polygons at least min_area large draw instead (with the paper's faint last dots a faint dot;
    // with solid dots, the default, a whole one where the fraction passes the same selection value, so that
    // the two regimes look alike: solid_dot_intensity). A polygon owed a stipple or more is drawn as in
    // regime (a). min_area thus decides where a fractional stipple gives way to a whole one drawn with that
    // probability. The selection values are uniform for polygons of every
    // size (src/stipple/selection_order.cpp), so the expected ink is the owed ink on any mesh.
    //
    // Beyond the paper's area test, the same test in stipples: min_area is given for the default D_max
    // (kMinAreaDensity: 4 px^2 then hold one stipple), so a polygon that could not hold min_area x
    // kMinAreaDensity stipples even where fully dark (its due candidates with the view's terms, before shading
    // and the enhancements that lighten) is selected too, however large on screen. At a low D_max (0.01: a
    // stipple's share of the screen is 100 px^2) every polygon drew a faint grey dot, a haze where an
    // illustrator expects sparse black dots (a walkthrough, 2026-12-05). At the default D_max and pr the two
    // tests agree for any min_area, but where a polygon's rounded candidate count falls short of its area.
    float scaling = scaling_distance(distance, q);
    float screen_area = p.area * q.pixels_per_unit * q.pixels_per_unit / (scaling * scaling) * orientation;
    result.screen_area = screen_area;
    bool holds_a_stipple = p.due * extrinsic * orientation >= q.min_area * kMinAreaDensity;
    if ((screen_area >= q.min_area && holds_a_stipple) || density <= 0.0f || density >= 1.0f) return result;
    result.probability = density;
    result.density = 1.0f;
    return result;
}

// The density of a polygon this frame with its selection value drawn: 0 when it is not selected.
STIPPLE_FN float selected_density(PolygonDensity d, float selection) {
    if (d.probability < 1.0f && selection >= d.probability) return 0.0f;
    return d.density;
}
STIPPLE_FN float polygon_density(PolygonView p, DensityParams q) {
    return selected_density(polygon_density_terms(p, q), p.selection);
}

// Beyond the paper: the density across a large polygon. The paper evaluates a polygon's density once, and
// we at its centroid; the terms that depend on where the eye sees a point (the intrinsic depth, the
// extrinsic scale s^pr with the orientation against the eye ray, the toon fade) then change in steps at
// the polygon's edges. On a coarse mesh the triangulation showed: the two triangles of one flat face of
// the morph cube differed in tone by about a quarter (yaw 45, pitch 35), and a floor of two triangles drew
// its far end as densely in object space as its near end (darker on screen) with no depth cue at all. So
// a polygon that covers more than kGradientAreaStart pixels draws each stipple at the density where it
// lies: the polygon's density times the place-dependent terms there over their value at the centroid
// (stipple_density_here). Where the density reaches a stipple's index depends on where it lies, so the
// polygon's drawn set is no longer a prefix of its candidates, and each stipple is drawn at its own
// fraction (§2.1's rule per stipple: intensities move continuously with the view, so nothing pops). The
// density pass stores the least and the most density any point of the polygon sees (conservative bounds,
// polygon_density_bounds): below the least every stipple is whole, and lists and work items run to the
// most. The place-dependent part fades in from kGradientAreaStart to kGradientAreaFull px^2 of the
// polygon's approximate screen area: smaller polygons show no step, and their densities stay the paper's.
STIPPLE_CONST float kGradientAreaStart = 16.0f;
STIPPLE_CONST float kGradientAreaFull = 64.0f;

// The place-dependent terms of polygon_density_terms at view-space point x of a polygon with unit normal
// `normal` (flipped toward the eye for a two-sided polygon seen from inside): (x) the intrinsic depth
// factor, (y) the extrinsic scale s^pr, (z) the facing ratio against the eye ray. point_terms multiplies
// them as the density does. Only their ratios over the centroid's are used, so the polygon's own
// scale_ratio (a constant factor of s^pr) cancels and is left out.
STIPPLE_FN vec3 point_term_parts(vec3 x, vec3 normal, DensityParams q) {
    // A point nearer than the near plane is never drawn; taken there, a corner behind the eye bounds the
    // density with a finite value.
    float distance = max(-x.z, max(q.near_plane, 1e-20f));
    vec3 parts = vec3(1.0f, 1.0f, abs(facing_ratio(normal, x, q)));
    if ((q.flags & kFlagIntrinsic) != 0u) parts.x = intrinsic_factor(q.center_depth - distance, q.half_range, q.de);
    if ((q.flags & kFlagExtrinsic) != 0u)
        parts.y = extrinsic_factor(q.pixels_per_unit / (scaling_distance(distance, q) * q.reference_ppu), q.pr);
    return parts;
}
STIPPLE_FN float facing_terms(float facing, DensityParams q) {
    float terms = 1.0f;
    if ((q.flags & kFlagToonFade) != 0u) terms *= toon_stipple_fade(facing, q.toon_sharpness);
    if ((q.flags & kFlagExtrinsic) != 0u) terms *= orientation_factor(facing);
    return terms;
}
STIPPLE_FN float point_terms(vec3 x, vec3 normal, DensityParams q) {
    vec3 parts = point_term_parts(x, normal, q);
    return parts.x * parts.y * facing_terms(parts.z, q);
}

// The point of triangle a, b, c nearest the eye (the origin): where a plane's facing ratio is largest
// (Ericson, Real-Time Collision Detection 5.1.5).
STIPPLE_FN vec3 triangle_point_nearest_eye(vec3 a, vec3 b, vec3 c) {
    vec3 ab = b - a, ac = c - a, ap = -a;
    float d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    vec3 bp = -b;
    float d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
    vec3 cp = -c;
    float d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
    float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    float sum = va + vb + vc;
    return sum > 0.0f ? (a * va + b * vb + c * vc) / sum : (a + b + c) * (1.0f / 3.0f);
}

// A polygon's unit normal in view space from its view-space corners, toward the eye if it is two-sided and
// seen from inside (as polygon_density_terms flips it).
STIPPLE_FN vec3 view_normal_of(vec3 a, vec3 b, vec3 c, DensityParams q) {
    vec3 n = cross(b - a, c - a);
    float len = length(n);
    n = len > 0.0f ? n / len : vec3(0.0f, 0.0f, 1.0f);
    if ((q.flags & kFlagTwoSided) != 0u && dot(n, toward_eye(a + b + c, q)) < 0.0f) n = -n;
    return n;
}

// Where a large polygon's density is evaluated (the point whose terms stipple_density_here divides by): its
// centroid, or, where the centroid lies nearer than the near plane (a floor of two huge triangles with the
// camera above it, whose centroids may lie behind the eye), a point of the part that can be drawn: on the way
// from the centroid to the farthest corner, halfway between the near plane and that corner in depth (inside
// the triangle, and not at a corner, which may be seen edge-on). Until 2026-12-05 such a polygon drew
// nothing (its density, taken at a centroid behind the eye, was zero). Each stipple's density is the
// reference's times the terms where it lies over the reference's, so where the reference is does not change
// it. No loop and no array: lavapipe runs this for every stipple of a varying polygon, whichever side of its
// branches a lane takes.
STIPPLE_FN vec3 density_reference_point(vec3 a, vec3 b, vec3 c, DensityParams q) {
    vec3 centre = (a + b + c) * (1.0f / 3.0f);
    vec3 far_corner = -a.z >= -b.z ? a : b;
    far_corner = -far_corner.z >= -c.z ? far_corner : c;
    float centre_depth = -centre.z, far_depth = -far_corner.z;
    // Nothing of it beyond the near plane, or the centroid already there: the centroid.
    if (centre_depth >= q.near_plane || !(far_depth > q.near_plane)) return centre;
    float t = (0.5f * (q.near_plane + far_depth) - centre_depth) / (far_depth - centre_depth);
    return mix(centre, far_corner, t);
}

// How much of the place-dependent density a polygon carries, from its approximate screen area (its
// view-space corners a, b, c): 0 below kGradientAreaStart px^2, 1 from kGradientAreaFull.
STIPPLE_FN float density_gradient_weight(vec3 a, vec3 b, vec3 c, DensityParams q) {
    vec3 centre = density_reference_point(a, b, c, q);
    float distance = -centre.z;
    if (distance <= 0.0f) return 0.0f;
    vec3 n = cross(b - a, c - a);
    float area = 0.5f * length(n);
    float facing = area > 0.0f ? abs(facing_ratio(n / (2.0f * area), centre, q)) : 0.0f;
    float scaling = scaling_distance(distance, q);
    float screen_area = area * q.pixels_per_unit * q.pixels_per_unit / (scaling * scaling) * orientation_factor(facing);
    return clamp((screen_area - kGradientAreaStart) / (kGradientAreaFull - kGradientAreaStart), 0.0f, 1.0f);
}

// Whether a polygon drawing `density` may carry any (a cheap test from its constants, before its corners
// are read; generous: its area estimate is the centroid's, not the corners').
STIPPLE_FN bool may_carry_gradient(PolygonView p, DensityParams q, float density) {
    float distance = -p.center.z;
    // A centroid nearer than the near plane: the density there is not the polygon's (PolygonDensity::unplaced).
    if (distance < q.near_plane + q.near_margin) return p.candidates > 0.0f && p.due > 0.0f;
    if (!(density > 0.0f)) return false;
    float facing = abs(facing_ratio(p.normal, p.center, q));
    float scaling = scaling_distance(distance, q);
    float screen_area = p.area * q.pixels_per_unit * q.pixels_per_unit / (scaling * scaling) * orientation_factor(facing);
    return 2.0f * screen_area > kGradientAreaStart;
}
// The same for a polygon whose terms are known: one drawn by probabilistic selection draws one whole stipple
// where it is selected, never spread by the place-dependent terms (a polygon large on screen is selected where
// it cannot hold a whole stipple: polygon_density_terms).
STIPPLE_FN bool may_carry_gradient(PolygonDensity terms, PolygonView p, DensityParams q, float density) {
    return terms.probability >= 1.0f && may_carry_gradient(p, q, density);
}

// The density where a stipple at view-space x lies, on a polygon with view-space corners a, b, c drawing
// `density` at its centroid.
STIPPLE_FN float stipple_density_here(float density, vec3 x, vec3 a, vec3 b, vec3 c, DensityParams q) {
    // A stipple nearer than the near plane is clipped: not drawn (nor counted, nor sized), whatever the
    // density its polygon reaches at the near plane.
    if (-x.z < q.near_plane) return 0.0f;
    float weight = density_gradient_weight(a, b, c, q);
    if (!(weight > 0.0f)) return density;
    vec3 normal = view_normal_of(a, b, c, q);
    float at_centre = point_terms(density_reference_point(a, b, c, q), normal, q);
    if (!(at_centre > 0.0f)) return density;
    return min(density * mix(1.0f, point_terms(x, normal, q) / at_centre, weight), kMostDensity);
}

// Bounds of stipple_density_here over the polygon: (least, most). Each term's extremes are at the corners
// (depth and distance change linearly over a plane), but for the facing ratio, largest at the point
// nearest the eye; the product of the terms' extremes bounds the product.
STIPPLE_FN vec2 polygon_density_bounds(float density, vec3 a, vec3 b, vec3 c, DensityParams q) {
    float weight = density_gradient_weight(a, b, c, q);
    vec3 normal = view_normal_of(a, b, c, q);
    float at_centre = point_terms(density_reference_point(a, b, c, q), normal, q);
    if (!(at_centre > 0.0f) || !(weight > 0.0f)) return vec2(density);
    vec3 pa = point_term_parts(a, normal, q), pb = point_term_parts(b, normal, q), pc = point_term_parts(c, normal, q);
    vec3 lo = min(pa, min(pb, pc)), hi = max(pa, max(pb, pc));
    float facing_most = point_term_parts(triangle_point_nearest_eye(a, b, c), normal, q).z;
    float least = lo.x * lo.y * facing_terms(lo.z, q) / at_centre;
    float most = hi.x * hi.y * facing_terms(max(hi.z, facing_most), q) / at_centre;
    return min(density * vec2(mix(1.0f, least, weight), mix(1.0f, most, weight)) * vec2(0.999f, 1.001f),
               vec2(kMostDensity));
}

// What the density pass stores for a polygon large on screen (listed for the gradient pass by
// may_carry_gradient), which stipple_density_here scales to each of its stipples: its density not capped at
// what its candidates can carry at the largest dots (kMaxStippleScale), the cap applying to each stipple
// (drawn_stipple_count, stipple_scale); capped and then scaled, a floor of two triangles close up read 0.057
// where the same floor in 40 x 40 cells read 0.099 (until 2026-12-05). With its centroid nearer than the near
// plane, minus the part of its density that does not depend on where a point lies (its gradient pass
// multiplies in the rest at the reference point: large_polygon_density). `density`: selected_density's.
STIPPLE_FN float large_polygon_stored_density(PolygonDensity d, float density) {
    if (d.unplaced > 0.0f) return -d.unplaced;
    return d.probability < 1.0f ? density : min(d.owed, kMostDensity);
}

// The density a large polygon carries at its reference point (density_reference_point), from what the density
// pass stored (large_polygon_stored_density) and its view-space corners.
STIPPLE_FN float large_polygon_density(float stored, vec3 a, vec3 b, vec3 c, DensityParams q) {
    if (!(stored < 0.0f)) return stored;
    // Nothing of it beyond the near plane: nothing to draw (its reference would be its centroid, where the
    // terms, taken at the near plane, would have every candidate drawn and clipped).
    if (!(max(-a.z, max(-b.z, -c.z)) > q.near_plane)) return 0.0f;
    vec3 normal = view_normal_of(a, b, c, q);
    return min(-stored * point_terms(density_reference_point(a, b, c, q), normal, q), kMostDensity);
}

#endif
