// The per-frame density (paper §2.1-2.3, §3.2) on the GPU: the compute pass against the CPU
// definition, the buffers an object holds, and the paper's claims (the last stipple's fraction, the
// probabilistic selection) as figures. The density paths against each other: test_gpu_density_paths.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <random>

#include "mesh/load_mesh.hpp"
#include "mesh/primitives.hpp"
#include "render/density_cpu.hpp"
#include "render/density_formulas.hpp"
#include "render/path_buffers.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class DensityPaths : public test::GpuTest {};
using test::Prepared;

std::string blobby_path() { return test::source_path("assets/blobby.glb"); }

// Disjoint random triangles with random stipple counts: a stress set for the formulas.
Prepared random_polygons(size_t count, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_real_distribution<float> log_size(std::log(1e-3f), std::log(0.3f));
    std::uniform_int_distribution<uint32_t> stipples(0, 12);
    Prepared p;
    p.stipples.first.push_back(0);
    for (size_t t = 0; t < count; ++t) {
        glm::vec3 center(unit(rng), unit(rng), unit(rng));
        float size = std::exp(log_size(rng));
        for (int k = 0; k < 3; ++k) {
            p.mesh.positions.push_back(center + size * glm::vec3(unit(rng), unit(rng), unit(rng)));
            p.mesh.indices.push_back(uint32_t(p.mesh.positions.size() - 1));
        }
        uint32_t n = stipples(rng);
        for (uint32_t i = 0; i < n; ++i) {
            p.stipples.positions.push_back(center);
            p.stipples.triangle.push_back(uint32_t(t));
        }
        p.stipples.first.push_back(uint32_t(p.stipples.positions.size()));
    }
    compute_vertex_normals(p.mesh);
    return p;
}

TEST_F(DensityPaths, ComputePassMatchesTheCpuDefinition) {
    std::mt19937 rng(7);
    Prepared polygons = random_polygons(10000, rng);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(polygons.mesh, polygons.stipples, glm::mat4(1.0f), ObjectParams{});
    OffscreenTarget target(*context, {320, 256});
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);

    size_t compared = 0, selection_regime = 0, drawn = 0, near_ties = 0, mismatched = 0, with_gradient = 0;
    double max_relative = 0.0, max_absolute = 0.0, max_gradient_relative = 0.0;
    for (int camera = 0; camera < 8; ++camera) {
        ObjectParams& params = renderer.params(0);
        params.shading_exponent = 0.5f + 3.5f * uniform(rng);
        params.pr = 4.0f * uniform(rng);
        params.de = 0.5f + 3.5f * uniform(rng);
        params.min_area = 2.0f + 7.0f * uniform(rng);
        params.shading = camera % 4 != 1;
        params.intrinsic = camera % 4 != 2;
        params.extrinsic = camera % 4 != 3;
        params.faint_dots = camera % 2 == 0;  // every other camera the last stipples solid or absent
        float distance = std::exp(std::log(0.6f) + uniform(rng) * std::log(60.0f / 0.6f));
        // One camera near for certain, where polygons large on screen hold enough stipples to carry a gradient:
        // these polygons hold 0-12 candidates whatever their size, and since 2026-12-05 one that cannot hold
        // min_area x 0.25 stipples even fully dark goes to probabilistic selection, however large on screen;
        // the random draws put no camera nearer than 5 framing distances, where all of them did.
        if (camera == 0) distance = 0.4f, params.pr = 2.0f, params.min_area = 2.0f;
        FrameView view = test::framed_view({glm::vec3(0.0f), 1.8f}, target.extent(), distance, 360.0f * uniform(rng),
                                           170.0f * uniform(rng) - 85.0f);
        view.light_view = glm::normalize(glm::vec3(uniform(rng), uniform(rng), uniform(rng)) - 0.5f);
        target.draw(renderer, view);

        std::vector<float> gpu = renderer.read_densities(0);
        const std::vector<glm::vec2> gpu_bounds = renderer.read_density_bounds(0);
        const ObjectGpu& object = renderer.object(0);
        std::vector<float> cpu(gpu.size());
        std::vector<glm::vec2> cpu_bounds(gpu.size());
        compute_densities_cpu(object.polygons.cpu, object.geometry.first_stipple, 0, object.polygons.corner_positions,
                              object.polygons.corner_indices, renderer.frame_uniforms(), object.frame.uniforms, cpu,
                              cpu_bounds);
        auto q = formulas::density_params(renderer.frame_uniforms(), object.frame.uniforms);
        for (size_t t = 0; t < gpu.size(); ++t) {
            auto terms = formulas::polygon_density_terms(formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), object.frame.uniforms), q);
            if (terms.probability < 1.0f) ++selection_regime;
            ++compared;
            if ((gpu[t] > 0.0f) != (cpu[t] > 0.0f)) {
                float u = formulas::polygon_selection(object.polygons.cpu[t]);
                // A tie at the selection, or (solid dots) at the end of a last stipple's fade, where its
                // intensity runs continuously to 0: one side a hair above it.
                if (std::abs(u - terms.probability) < 1e-5f || std::abs(gpu[t] - cpu[t]) < 1e-3f) ++near_ties;
                else ++mismatched;
                continue;
            }
            if (cpu[t] > 0.0f) ++drawn;
            if (cpu_bounds[t].x != cpu_bounds[t].y) ++with_gradient;
            // Errors relative to the density, floored at a twentieth of a stipple (a 5% grey dot): the GPU's
            // transcendental functions differ from the C library's in the last bits. With solid dots a flat
            // polygon's last stipple is a ramp of its density's fraction, 1 / band steep (solid_dot_intensity):
            // there the error is relative to the density before it, scaled by that steepness.
            double scale = std::max(double(std::abs(cpu[t])), 0.05);
            if (!params.faint_dots && cpu_bounds[t].x == cpu_bounds[t].y && cpu[t] > 0.0f) {
                const float unfolded = formulas::selected_density(terms, formulas::polygon_selection(object.polygons.cpu[t]));
                const float fraction = unfolded - std::floor(unfolded);
                const float band = std::min(formulas::kSolidDotBand, 2.0f * std::min(fraction, 1.0f - fraction));
                if (band > 0.0f) scale = std::max(double(unfolded), 0.05) * std::max(1.0, 1.0 / double(band));
            }
            // The bounds of a large polygon's density, relative to the density as the density is (floored alike).
            const double bounds_error = glm::length(glm::dvec2(gpu_bounds[t]) - glm::dvec2(cpu_bounds[t]));
            max_gradient_relative = std::max(max_gradient_relative, bounds_error / scale);
            double absolute = std::abs(double(gpu[t]) - cpu[t]);
            max_absolute = std::max(max_absolute, absolute);
            max_relative = std::max(max_relative, absolute / scale);
        }
    }
    std::printf("compared %zu densities: %zu drawn, %zu in the selection regime, max relative error %.3g, "
                "max absolute error %.3g stipples, %zu near-tie selections, %zu mismatched selections\n",
                compared, drawn, selection_regime, max_relative, max_absolute, near_ties, mismatched);
    std::printf("%zu polygons large enough on screen to draw at the density where each stipple lies; max relative "
                "error of their density bounds %.3g\n", with_gradient,
                max_gradient_relative);
    EXPECT_LE(max_relative, 1e-4);
    EXPECT_LE(max_gradient_relative, 1e-4);
    EXPECT_GT(with_gradient, 0u) << "the near cameras should put a few polygons large on screen";
    EXPECT_EQ(mismatched, 0u);
    EXPECT_GT(selection_regime, 1000u) << "the cameras should exercise probabilistic selection";
    EXPECT_GT(drawn, 5000u);
}

TEST_F(DensityPaths, PackedPolygonConstantsKeepCentroidNormalAreaAndSelection) {
    // TriangleInfo is 16 bytes: 16-bit centroids in the object's box, an octahedral 16-bit normal.
    std::mt19937 rng(11);
    Prepared polygons = random_polygons(20000, rng);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(polygons.mesh, polygons.stipples, glm::mat4(1.0f), ObjectParams{});
    const ObjectGpu& object = renderer.object(0);
    gpu::ObjectUniforms identity{};
    identity.model_view = identity.normal_view = glm::mat4(1.0f);
    identity.extrinsic.w = 1.0f;
    identity.box_min = glm::vec4(object.polygons.box_min, 0.0f);
    identity.box_size = glm::vec4(object.polygons.box_size, 0.0f);
    const float box = std::max({object.polygons.box_size.x, object.polygons.box_size.y, object.polygons.box_size.z});
    double worst_center = 0.0, worst_normal_deg = 0.0, worst_area = 0.0;
    size_t wrong_counts = 0;
    for (size_t t = 0; t < object.geometry.triangle_count; ++t) {
        const Mesh& m = polygons.mesh;
        glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                  c = m.positions[m.indices[3 * t + 2]];
        // The truth in double (the packing computes in double: a float cross product overflows for
        // polygons beyond ~1e9 units and is 2.5e-6 off for thin ones here).
        const glm::dvec3 cross = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
        auto p = formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), identity);
        worst_center = std::max(worst_center, double(glm::length(p.center - (a + b + c) / 3.0f)) / box);
        glm::dvec3 exact = glm::normalize(cross), packed = glm::dvec3(p.normal);
        double angle = std::atan2(glm::length(glm::cross(exact, packed)), glm::dot(exact, packed));
        worst_normal_deg = std::max(worst_normal_deg, angle * 180.0 / 3.14159265358979);
        worst_area = std::max(worst_area, std::abs(double(p.area) / (0.5 * glm::length(cross)) - 1.0));
        wrong_counts += p.candidates != float(polygons.stipples.count(t));
        EXPECT_GT(p.selection, 0.0f);
        EXPECT_LT(p.selection, 1.0f);
    }
    std::printf("packed constants: centroid error %.2g of the box, normal error %.3g degrees, area error %.2g\n",
                worst_center, worst_normal_deg, worst_area);
    EXPECT_LE(worst_center, 1.0 / 65535.0);
    EXPECT_LE(worst_normal_deg, 0.01);
    EXPECT_LE(worst_area, 1e-6);
    EXPECT_EQ(wrong_counts, 0u);
}

TEST_F(DensityPaths, AnObjectHoldsOnlyTheBuffersOfThePathsItDrawsWith) {
    ObjectParams params;
    params.density_path = DensityPath::Vertex;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(blob.mesh, blob.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {320, 256});
    FrameView view = test::framed_view(compute_bounding_sphere(blob.mesh), target.extent(), 1.5f);
    const ObjectGpu& object = renderer.object(0);
    auto sizes = [&] {
        std::vector<VkDeviceSize> s;
        for (PathBuffer kind : kPathBuffers) s.push_back(path_buffer(object.frame, kind).size());
        return s;
    };
    const VkDeviceSize placeholder = kPathBufferPlaceholderBytes;
    // Every path that computes the densities on the GPU lists the polygons large on screen for the
    // density's gradient pass: a header, then room for every polygon.
    const VkDeviceSize gradient = 16 + 4 * VkDeviceSize(object.geometry.triangle_count);
    // The vertex path's chunks of the polygons whose density changes across them (GradientChunks): a draw
    // command, then at most one per polygon and one per kGradientChunk candidates.
    const VkDeviceSize chunks =
        16 + 4 * (VkDeviceSize(object.geometry.triangle_count) + object.geometry.stipple_count / gpu::kGradientChunk);
    target.draw(renderer, view);
    EXPECT_EQ(sizes(), (std::vector<VkDeviceSize>{placeholder, placeholder, chunks, gradient, placeholder}))
        << "the vertex path needs only the gradient pass's lists";
    renderer.params(0).density_path = DensityPath::Splat;
    target.draw(renderer, view);
    // The work list: a header, then at most one item per polygon and one per kSplatShortRun candidates; as
    // large, the varying polygons' items (every polygon may vary) in the binding of the vertex path's chunks
    // (grown), and the items astride the outline (the ring pass).
    const VkDeviceSize items = object.geometry.triangle_count + object.geometry.stipple_count / gpu::kSplatShortRun;
    const VkDeviceSize list = 16 + 4 * items;
    ASSERT_GT(list, chunks);
    EXPECT_EQ(sizes(), (std::vector<VkDeviceSize>{list, placeholder, list, gradient, list}));

    // With the splat path, what the object costs on the GPU per candidate: 11 bytes per candidate (the
    // stipple and its share of the three lists: the work list, the varying polygons' and the ring pass's)
    // and 48 per polygon besides the mesh, so at most 23 where candidates outnumber polygons ~4 to 1; the
    // blobby surface has ~18 candidates a polygon.
    VkDeviceSize bytes = object.geometry.positions.size() + object.geometry.normals.size() + object.geometry.indices.size() +
                         object.geometry.stipples.size() + object.polygons.gpu.size() + object.frame.triangle_draw.size() +
                         object.frame.debug.size() + object.frame.object_uniforms.size();
    for (PathBuffer kind : kPathBuffers) bytes += path_buffer(object.frame, kind).size();
    double per_candidate = double(bytes) / double(object.geometry.stipple_count);
    std::printf("blobby: %u polygons, %u candidates, %.2f GPU bytes per candidate with the splat path\n",
                object.geometry.triangle_count, object.geometry.stipple_count, per_candidate);
    EXPECT_EQ(object.geometry.stipples.size(), 8u * object.geometry.stipple_count);
    EXPECT_EQ(object.polygons.gpu.size(), 16u * object.geometry.triangle_count);
    EXPECT_LE(per_candidate, 19.0);

    // The indirect path's list of survivors: a draw command, then room for every candidate; it keeps the
    // work list it is made from.
    renderer.params(0).density_path = DensityPath::Indirect;
    target.draw(renderer, view);
    const VkDeviceSize survivors = 16 + 4 * VkDeviceSize(object.geometry.stipple_count);
    EXPECT_EQ(sizes(), (std::vector<VkDeviceSize>{list, placeholder, survivors, gradient, list}));
}

// One triangle facing the camera, five stipples far apart, lit at `light_deg` with shading only: the
// density is 5 * (1 - cos(light_deg)), the ink owed where the light falls at that angle. What each stipple's dot looks like: the luminance at its centre and its
// pixels darker than mid-grey.
struct FiveStipples {
    float density;
    float threshold;  // the polygon's selection value (solid_dot_intensity)
    std::vector<int> centre, dark;
};

FiveStipples draw_five_stipples(gpu::Context& context, float point_size, DensityPath path, float light_deg,
                                bool faint_dots = true, float distance = 1.0f) {
    Mesh mesh;
    mesh.positions = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    mesh.indices = {0, 1, 2};
    compute_vertex_normals(mesh);
    StippleSet stipples;
    stipples.positions = {{-0.5f, -0.6f, 0.0f}, {0.5f, -0.6f, 0.0f}, {0.0f, 0.4f, 0.0f}, {0.0f, -0.6f, 0.0f},
                          {0.0f, -0.1f, 0.0f}};
    stipples.triangle.assign(5, 0u);
    stipples.first = {0, 5};
    ObjectParams params;
    params.extrinsic = false;
    params.intrinsic = false;
    params.point_size = point_size;
    params.density_path = path;
    params.faint_dots = faint_dots;
    StippleRenderer renderer(context, kColorFormat, context.depth_format);
    renderer.add_object(mesh, stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(context, {256, 256});
    FrameView view = test::framed_view({glm::vec3(0.0f), 1.2f}, target.extent(), distance, 0.0f, 0.0f);
    view.light_view = glm::vec3(std::sin(glm::radians(light_deg)), 0.0f, std::cos(glm::radians(light_deg)));
    RenderedFrame frame = target.render(renderer, view);

    FiveStipples result;
    result.density = renderer.read_densities(0)[0];
    result.threshold = formulas::polygon_selection(renderer.object(0).polygons.cpu[0]);
    glm::mat4 view_proj = view.camera.proj * view.camera.view;
    for (const glm::vec3& p : stipples.positions) {
        glm::vec4 clip = view_proj * glm::vec4(p, 1.0f);
        int x = int((clip.x / clip.w * 0.5f + 0.5f) * 256.0f);
        int y = int((0.5f - clip.y / clip.w * 0.5f) * 256.0f);  // top row first
        result.centre.push_back(luminance(frame.color, x, y));
        int inked = 0;
        for (int dy = -5; dy <= 5; ++dy)
            for (int dx = -5; dx <= 5; ++dx) inked += luminance(frame.color, x + dx, y + dy) < 100;
        result.dark.push_back(inked);
    }
    std::printf("%s, %.0f px, density %.3f: luminances %d %d %d %d %d, dark pixels %d %d %d %d %d\n",
                density_path_name(path), point_size, result.density, result.centre[0], result.centre[1],
                result.centre[2], result.centre[3], result.centre[4], result.dark[0], result.dark[1], result.dark[2],
                result.dark[3], result.dark[4]);
    return result;
}

TEST_F(DensityPaths, LastStippleCarriesTheFractionalDensity) {
    // Lit at 60 degrees, the density is 2.5: two stipples are full, one is half and two are culled.
    // Points of 2 px (the paper's kind): the half one has half the ink's intensity (§2.1). Round dots of
    // 5 px: the half one is a dot of full ink and half the area (fractional_round_dot), on every path.
    for (const float point_size : {2.0f, 5.0f})
        for (const DensityPath path : {DensityPath::Splat, DensityPath::Vertex}) {
            SCOPED_TRACE(std::string(density_path_name(path)) + ", " + std::to_string(point_size) + " px");
            const FiveStipples drawn = draw_five_stipples(*context, point_size, path, 60.0f);
            EXPECT_NEAR(drawn.density, 2.5f, 1e-5f);
            EXPECT_EQ(drawn.centre[0], 0);
            EXPECT_EQ(drawn.centre[1], 0);
            EXPECT_EQ(drawn.centre[3], 255);
            EXPECT_EQ(drawn.centre[4], 255);
            if (point_size < 2.5f) {
                EXPECT_NEAR(drawn.centre[2], 128, 2);  // half the ink over white paper
                EXPECT_EQ(drawn.dark[2], 0);
            } else {
                EXPECT_EQ(drawn.centre[2], 0);  // full ink, on a smaller dot
                EXPECT_GT(drawn.dark[0], 15);
                EXPECT_NEAR(double(drawn.dark[2]) / double(drawn.dark[0]), 0.5, 0.2);
            }
        }
}

// Solid dots (the default): the same triangle's third stipple, whose fraction f the light sets, is absent below
// its polygon's threshold u and solid above it (beyond half the band), on every path and for both kinds of dot;
// within the band it fades. Density 5 (1 - cos angle) with every term but shading off.
TEST_F(DensityPaths, SolidDotsAreWholeOrAbsentByThePolygonsThreshold) {
    const float u = draw_five_stipples(*context, 2.0f, DensityPath::Splat, 60.0f, false).threshold;
    std::printf("the triangle's threshold %.4f\n", u);
    const float half_band = 0.5f * formulas::kSolidDotBand;
    size_t checked = 0;
    for (const float fraction : {u - 3.0f * half_band, u + 3.0f * half_band, u}) {
        if (!(fraction > 0.01f && fraction < 0.99f)) continue;
        const float light_deg = glm::degrees(std::acos(1.0f - (2.0f + fraction) / 5.0f));
        for (const float point_size : {2.0f, 5.0f})
            for (const DensityPath path : {DensityPath::Splat, DensityPath::Vertex, DensityPath::Cpu}) {
                SCOPED_TRACE(std::string(density_path_name(path)) + ", " + std::to_string(point_size) + " px, f " +
                             std::to_string(fraction));
                const FiveStipples drawn = draw_five_stipples(*context, point_size, path, light_deg, false);
                EXPECT_EQ(drawn.centre[0], 0);
                EXPECT_EQ(drawn.centre[1], 0);
                EXPECT_EQ(drawn.centre[3], 255);
                // (The polygon, large on screen, decides each stipple where it lies: the density read back is
                // its own, 2 + f, and the image shows the rule.)
                EXPECT_NEAR(drawn.density, 2.0f + fraction, 1e-4f);
                if (fraction < u - half_band) {
                    EXPECT_EQ(drawn.centre[2], 255) << "below its threshold the last stipple is not drawn";
                } else if (fraction > u + half_band) {
                    EXPECT_EQ(drawn.centre[2], 0) << "above its threshold it is whole";
                    EXPECT_NEAR(double(drawn.dark[2]) / double(drawn.dark[0]), 1.0, 0.25) << "a dot of full size";
                } else if (point_size < 2.5f) {  // at the threshold, halfway through its fade
                    EXPECT_NEAR(drawn.centre[2], 128, 3);
                } else {
                    EXPECT_NEAR(double(drawn.dark[2]) / double(drawn.dark[0]), 0.5, 0.2);
                }
                // Far away (a few pixels: drawn flat, not decided stipple by stipple) the density pass, or the
                // CPU's, stores the whole stipples and the last one's intensity (whatever the dots' size).
                if (point_size < 2.5f) {
                    const float flat = draw_five_stipples(*context, point_size, path, light_deg, false, 80.0f).density;
                    EXPECT_NEAR(flat, fraction < u - half_band ? 2.0f : fraction > u + half_band ? 3.0f : 2.5f, 1e-3f);
                }
                ++checked;
            }
    }
    EXPECT_GE(checked, 12u) << "the threshold leaves room on one side at least";
}

// The look solid dots are for: a fine mesh framed, whose polygons hold about a stipple each, is drawn in black
// dots (the paper's faint last dots make most of its ink grey), with the same mean ink.
TEST_F(DensityPaths, SolidDotsDrawAFineMeshInBlackDotsWithTheSameInk) {
    ObjectParams params;
    const Prepared sphere = test::prepare(make_uv_sphere(120000), params);
    double grey_share[2] = {0.0, 0.0}, ink[2] = {0.0, 0.0};
    for (const bool faint : {false, true}) {
        params.faint_dots = faint;
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(sphere.mesh, sphere.stipples, glm::mat4(1.0f), params);
        OffscreenTarget target(*context, {512, 512});
        const RenderedFrame frame = target.render(renderer, test::framed_view({glm::vec3(0.0f), 1.0f}, target.extent(), 0.9f));
        size_t black = 0, grey = 0;
        double sum = 0.0;
        size_t covered = 0;
        for (size_t i = 0; i < frame.depth.size(); ++i) {
            if (frame.depth[i] >= 1.0f) continue;
            ++covered;
            const int l = luminance(frame.color, int(i % 512), int(i / 512));
            sum += (255.0 - l) / 255.0;
            black += l == 0;
            grey += l > 0 && l < 255;
        }
        grey_share[faint] = double(grey) / double(std::max<size_t>(black + grey, 1));
        ink[faint] = sum / double(std::max<size_t>(covered, 1));
    }
    std::printf("grey share of the inked pixels: solid dots %.3f, faint dots %.3f; mean ink %.4f, %.4f\n", grey_share[0],
                grey_share[1], ink[0], ink[1]);
    EXPECT_LT(grey_share[0], 0.1);  // 0.039 measured
    EXPECT_GT(grey_share[1], 0.25);  // 0.341
    EXPECT_NEAR(ink[0] / ink[1], 1.0, 0.03);
}

TEST_F(DensityPaths, SmallFractionsOfRoundDotsAreSmallBlackDots) {
    // Round dots of 4 px at density 2.2 (lit at acos 0.56): the last stipple's fraction 0.2 is a dot of
    // side 4 sqrt(0.2) = 1.8 px, still of full ink (kShrunkDotMinSide), not a faded dot the size of a
    // larger one: at low density on a fine mesh most dots are such fractions, and faded they read as a
    // grey wash rather than stippling. Its area, so its ink, is a fifth of a whole dot's.
    const float light_deg = glm::degrees(std::acos(0.56f));
    for (const DensityPath path : {DensityPath::Splat, DensityPath::Vertex}) {
        SCOPED_TRACE(density_path_name(path));
        const FiveStipples drawn = draw_five_stipples(*context, 4.0f, path, light_deg);
        EXPECT_NEAR(drawn.density, 2.2f, 1e-4f);
        EXPECT_EQ(drawn.centre[0], 0);
        EXPECT_EQ(drawn.centre[2], 0) << "the fractional dot should be black";
        EXPECT_GE(drawn.dark[2], 1);
        EXPECT_LE(drawn.dark[2], 5) << "the fractional dot should be small";
        EXPECT_GT(drawn.dark[0], 9);
        EXPECT_EQ(drawn.centre[3], 255);
    }
}

TEST_F(DensityPaths, ProbabilisticSelectionMatchesItsExpectationAndIsStable) {
    ObjectParams params;
    params.intrinsic = false;
    Prepared grid = test::prepare(make_grid(200), params);  // 80,000 small triangles
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
    renderer.add_object(grid.mesh, grid.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {1280, 1024});
    FrameView view = test::framed_view(compute_bounding_sphere(grid.mesh), target.extent(), 10.0f, 15.0f, 20.0f);
    target.draw(renderer, view);
    std::vector<float> densities = renderer.read_densities(0);
    std::vector<uint32_t> first_mask = renderer.drawn_mask(0);

    const ObjectGpu& object = renderer.object(0);
    auto q = formulas::density_params(renderer.frame_uniforms(), object.frame.uniforms);
    double expected = 0.0, variance = 0.0;
    size_t in_regime = 0, drawn = 0;
    for (size_t t = 0; t < densities.size(); ++t) {
        auto terms = formulas::polygon_density_terms(formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), object.frame.uniforms), q);
        if (terms.density <= 0.0f) continue;
        expected += terms.probability;
        variance += terms.probability * (1.0 - terms.probability);
        in_regime += terms.probability < 1.0f;
        drawn += densities[t] > 0.0f;
    }
    double n = double(densities.size());
    double share = drawn / n, expected_share = expected / n, sigma = std::sqrt(variance) / n;
    std::printf("selection: %zu of %zu polygons in the regime; drawn share %.5f, expected %.5f +- %.5f (1 sd)\n",
                in_regime, densities.size(), share, expected_share, sigma);
    EXPECT_GT(in_regime, densities.size() / 2);
    EXPECT_LT(expected_share, 0.5) << "most tiny polygons should be skipped";
    EXPECT_LE(std::abs(share - expected_share), 3.0 * sigma);

    for (int frame = 0; frame < 3; ++frame) {
        target.draw(renderer, view);
        EXPECT_EQ(renderer.drawn_mask(0), first_mask) << "a still camera must draw the same polygons every frame";
    }
}

}  // namespace
}  // namespace stipple
