// Open surfaces (issue 13): looking into an open bowl, no line kind inks the back faces seen through
// the opening as a solid patch; with two_sided those back faces get stipples by the outside's tone
// rule (their normal flipped), on every density path.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "render/density_formulas.hpp"
#include "stipple/selection_order.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class OpenSurfaces : public test::GpuTest {};

constexpr VkExtent2D kExtent{384, 384};
constexpr float kYaw = 25.0f, kPitch = 55.0f;  // above the bowl, looking into it

Mesh reversed_winding(Mesh mesh) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    for (glm::vec3& n : mesh.normals) n = -n;
    return mesh;
}

FrameView bowl_view(const Mesh& mesh) {
    return test::framed_view(compute_bounding_sphere(mesh), kExtent, 1.0f, kYaw, kPitch);
}

RenderedFrame render(gpu::Context& context, const test::Prepared& object, const ObjectParams& params) {
    StippleRenderer renderer(context, kColorFormat, context.depth_format);
    renderer.add_object(object.mesh, object.stipples, object.model, params);
    OffscreenTarget target(context, kExtent);
    return target.render(renderer, bowl_view(object.mesh));
}

// The opening: pixels where a back face is the nearest surface (the reversed mesh's front faces are
// nearer than the mesh's own, or the mesh's own do not cover the pixel).
std::vector<uint8_t> opening_mask(gpu::Context& context, const test::Prepared& bowl, const test::Prepared& inside_out) {
    ObjectParams plain;
    // The depth of the faces facing the eye alone: an open mesh's depth pass holds its back faces too
    // (depth_holds_back_faces), so each is drawn as a mesh its loading found closed (no border edge counted).
    auto front_faces_only = [](test::Prepared p) {
        p.mesh.winding.parts = 1;
        p.mesh.winding.border_edges = 0;
        return p;
    };
    std::vector<float> front = render(context, front_faces_only(bowl), plain).depth;
    std::vector<float> back = render(context, front_faces_only(inside_out), plain).depth;
    std::vector<uint8_t> mask(front.size());
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = back[i] < 1.0f && back[i] < front[i];
    return mask;
}

// The largest distance (chessboard steps) from an inked pixel of the opening to the nearest pixel
// that is not inked: a solid patch of ink n pixels across reaches about n / 2.
int thickest_ink(const RenderedFrame& frame, const std::vector<uint8_t>& opening) {
    const int w = int(kExtent.width), h = int(kExtent.height);
    std::vector<int> d(size_t(w) * h, -1);
    std::deque<int> queue;
    for (int i = 0; i < w * h; ++i)
        if (frame.color.pixels[4 * size_t(i)] >= 128) d[size_t(i)] = 0, queue.push_back(i);
    while (!queue.empty()) {
        int i = queue.front();
        queue.pop_front();
        int x = i % w, y = i / w;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int u = x + dx, v = y + dy;
                if (u < 0 || v < 0 || u >= w || v >= h || d[size_t(v) * w + u] >= 0) continue;
                d[size_t(v) * w + u] = d[size_t(i)] + 1;
                queue.push_back(v * w + u);
            }
    }
    int thickest = 0;
    for (size_t i = 0; i < d.size(); ++i)
        if (opening[i]) thickest = std::max(thickest, d[i]);
    return thickest;
}

double mean_ink(const RenderedFrame& frame, const std::vector<uint8_t>& region) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < region.size(); ++i)
        if (region[i]) sum += 1.0 - frame.color.pixels[4 * i] / 255.0, ++n;
    return n ? sum / double(n) : 0.0;
}

TEST_F(OpenSurfaces, NoLineKindInksTheOpeningSolid) {
    ObjectParams params;
    params.generation.max_stipples = 30000;
    // Wide lines on a mesh finer than their width: drawn over every back face seen through the
    // opening (as the full Raskar-Cohen set drew them), they would ink it solid.
    params.silhouette_width = 8.0f;
    params.silhouette_thinning = false;
    test::Prepared bowl = test::prepare(test::make_open_hemisphere(96, 24), params);
    test::Prepared inside_out = test::prepare(reversed_winding(bowl.mesh), params);
    std::vector<uint8_t> opening = opening_mask(*context, bowl, inside_out);
    size_t opening_px = size_t(std::count(opening.begin(), opening.end(), 1));
    ASSERT_GT(opening_px, kExtent.width * kExtent.height / 8) << "the view should look into the bowl";

    struct Kind {
        const char* name;
        void (*set)(ObjectParams&);
    };
    const Kind kinds[] = {{"silhouette lines", [](ObjectParams& p) { p.silhouette_lines = true; }},
                          {"contours", [](ObjectParams& p) { p.contours = true; }},
                          {"borders", [](ObjectParams& p) { p.borders = true; }},
                          {"creases", [](ObjectParams& p) { p.creases = true; }},
                          {"all", [](ObjectParams& p) { p.silhouette_lines = p.contours = p.borders = p.creases = true; }}};
    for (DensityPath path : kAllDensityPaths)
        for (const Kind& kind : kinds) {
            if (path != ObjectParams{}.density_path && std::string(kind.name) != "all") continue;
            ObjectParams p = params;
            p.density_path = path;
            kind.set(p);
            StippleRenderer renderer(*context, kColorFormat, context->depth_format);
            renderer.add_object(bowl.mesh, bowl.stipples, bowl.model, p);
            OffscreenTarget target(*context, kExtent);
            RenderedFrame frame = target.render(renderer, bowl_view(bowl.mesh));
            const float width = renderer.object(0).frame.line_width;
            int thickest = thickest_ink(frame, opening);
            std::printf("%-9s %-16s: line width %.2f px; opening %zu px, mean ink %.3f, thickest ink %d px from paper\n",
                        density_path_name(path), kind.name, width, opening_px, mean_ink(frame, opening), thickest);
            if (std::string(kind.name) == "all" && path == ObjectParams{}.density_path)
                write_png(test::output_path("open_bowl_all_lines.png").string(), frame.color);
            // A line is at most `width` across: no ink lies farther than half of it (and a pixel) from paper.
            EXPECT_LE(thickest, int(std::ceil(0.5f * width)) + 1) << density_path_name(path) << " " << kind.name;
        }
}

TEST_F(OpenSurfaces, TwoSidedStipplesTheInsideByTheOutsidesToneRule) {
    ObjectParams params;
    test::Prepared bowl = test::prepare(test::make_open_hemisphere(64, 16), params);
    // The same bowl turned inside out: its inside is made of front faces, whose normals point inward.
    test::Prepared inside_out = test::prepare(reversed_winding(bowl.mesh), params);
    // Its polygons drawn with the bowl's selection values (§2.3): they rank a polygon by its first stipple,
    // which its own generation places elsewhere in the flipped triangle.
    bowl.stipples.selection = polygon_selection_values(bowl.mesh, bowl.stipples, params.generation.seed);
    inside_out.stipples.selection = bowl.stipples.selection;
    std::vector<uint8_t> opening = opening_mask(*context, bowl, inside_out);
    const FrameView view = bowl_view(bowl.mesh);
    for (DensityPath path : kAllDensityPaths) {
        ObjectParams one_sided = params, two_sided = params;
        one_sided.density_path = two_sided.density_path = path;
        two_sided.two_sided = true;
        // The bowl one-sided, two-sided, and the inside-out bowl, each alone in its frame.
        OffscreenTarget target(*context, kExtent);
        std::vector<std::unique_ptr<StippleRenderer>> renderers;
        std::vector<RenderedFrame> frames;
        std::vector<std::vector<float>> densities;
        for (int shown = 0; shown < 3; ++shown) {
            renderers.push_back(std::make_unique<StippleRenderer>(*context, kColorFormat, context->depth_format));
            const test::Prepared& object = shown == 2 ? inside_out : bowl;
            renderers.back()->add_object(object.mesh, object.stipples, object.model, shown == 1 ? two_sided : one_sided);
            frames.push_back(target.render(*renderers.back(), view));
            densities.push_back(renderers.back()->read_densities(0));
        }
        // Per polygon: the two-sided density is the one-sided one where the polygon faces the viewer
        // and the inside-out bowl's where it faces away (same candidates, the normal flipped).
        const ObjectGpu& object = renderers[0]->object(0);
        size_t away = 0, differ = 0;
        double inside_two = 0.0, inside_reference = 0.0;
        for (size_t t = 0; t < densities[0].size(); ++t) {
            auto p = formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), object.frame.uniforms);
            bool faces_away = formulas::polygon_faces_away(p.center, p.normal, formulas::DensityParams{});  // perspective
            float expected = faces_away ? densities[2][t] : densities[0][t];
            if (faces_away) ++away, inside_two += densities[1][t], inside_reference += densities[2][t];
            // The flipped normal is encoded apart (16-bit octahedral), so allow its rounding, and a
            // polygon right at its selection threshold may go either way.
            differ += std::abs(densities[1][t] - expected) > 1e-3f * std::max(1.0f, expected);
        }
        const double tone_one = mean_ink(frames[0], opening), tone_two = mean_ink(frames[1], opening),
                     tone_reference = mean_ink(frames[2], opening);
        std::printf("%-9s: %zu of %zu polygons face away; two-sided stipples inside %.0f, inside-out bowl %.0f; %zu "
                    "polygons differ; ink in the opening: one-sided %.3f, two-sided %.3f, inside-out %.3f\n",
                    density_path_name(path), away, densities[0].size(), inside_two, inside_reference, differ,
                    tone_one, tone_two, tone_reference);
        if (path == ObjectParams{}.density_path) {
            write_png(test::output_path("open_bowl_one_sided.png").string(), frames[0].color);
            write_png(test::output_path("open_bowl_two_sided.png").string(), frames[1].color);
        }
        EXPECT_GT(away, densities[0].size() / 4);
        EXPECT_LE(differ, densities[0].size() / 200) << density_path_name(path);
        EXPECT_NEAR(inside_two, inside_reference, 0.01 * inside_reference) << density_path_name(path);
        EXPECT_LT(tone_one, 0.02) << density_path_name(path);  // one-sided: paper through the opening
        EXPECT_NEAR(tone_two, tone_reference, 0.1 * tone_reference) << density_path_name(path);
    }
}

}  // namespace
}  // namespace stipple
