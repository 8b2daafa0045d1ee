// The density paths (vertex, cpu, indirect, splat, cpu-splat) against each other: the same stipples
// drawn, the same images, every stipple of large polygons, large dots as whole discs. The density
// pass against its CPU definition: test_gpu_density.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>

#include "mesh/load_mesh.hpp"
#include "mesh/mesh.hpp"
#include "render/density_formulas.hpp"
#include "render/path_buffers.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

// The suite keeps the name it had when these tests shared test_gpu_density.cpp (.ci/run names them).
class DensityPaths : public test::GpuTest {};
using test::Prepared;

std::string blobby_path() { return test::source_path("assets/blobby.glb"); }

// A 12-triangle box: a few thousand drawn stipples per polygon when framed, far more than one splat
// work item (kSplatChunk at most) carries.
Mesh make_box() {
    Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back(glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f));
    mesh.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    compute_vertex_normals(mesh);
    return mesh;
}

// A list of the splat's (DrawnPolygons header, then the items), its items sorted; checks its dispatch.
std::vector<uint32_t> read_splat_list(const gpu::Context& context, const gpu::Buffer& buffer, const char* what) {
    std::vector<std::byte> list = gpu::read_buffer(context, buffer);
    gpu::DrawnPolygons header;
    std::memcpy(&header, list.data(), sizeof header);
    std::vector<uint32_t> items(header.count);
    if (header.count > 0) std::memcpy(items.data(), list.data() + sizeof header, sizeof(uint32_t) * header.count);
    std::sort(items.begin(), items.end());
    EXPECT_EQ(header.groups_x, (header.count + gpu::kDensityWorkgroupSize - 1) / gpu::kDensityWorkgroupSize) << what;
    EXPECT_EQ(header.groups_y, 1u) << what;
    EXPECT_EQ(header.groups_z, 1u) << what;
    return items;
}

// The splat's work list holds, for each polygon that draws, its runs of splat_run_length stipples up to
// the most density any of them sees (TriangleDraw::most; the density, but on polygons large on screen),
// named by their first stipple, and nothing else. With GPU densities the runs of the polygons whose density
// varies across them (least < most) are listed apart (kSplatListVarying), and the others in the work list.
// The ring pass's list holds work items (those with a dot astride the outline), each once.
void expect_splat_work_list(const gpu::Context& context, StippleRenderer& renderer, const StippleSet& stipples,
                            DensityPath path) {
    const ObjectGpu& object = renderer.object(0);
    const std::vector<uint32_t> listed = read_splat_list(context, object.frame.drawn_polygons, "work list");
    const bool apart = path == DensityPath::Splat;
    const std::vector<uint32_t> varied =
        apart ? read_splat_list(context, object.frame.drawn_stipples, "varying polygons' list") : std::vector<uint32_t>{};
    std::vector<float> densities = renderer.read_densities(0);
    const std::vector<glm::vec2> bounds = renderer.read_density_bounds(0);
    std::vector<uint32_t> expected, expected_varied;
    for (uint32_t t = 0; t < densities.size(); ++t) {
        if (!(densities[t] > 0.0f)) continue;
        const uint32_t candidates = stipples.first[t + 1] - stipples.first[t];
        uint32_t drawn = formulas::drawn_stipple_count(bounds[t].y, candidates);
        const float point_size = object.frame.uniforms.shading.y;  // as drawn (drawn_point_size)
        const float side = formulas::splat_dot_side(point_size, densities[t], float(candidates));
        const uint32_t run = formulas::splat_run_length(drawn, side, point_size);
        std::vector<uint32_t>& into = apart && bounds[t].x != bounds[t].y ? expected_varied : expected;
        for (uint32_t k = 0; k < drawn; k += run) into.push_back(stipples.first[t] + k);
    }
    EXPECT_EQ(listed, expected) << density_path_name(path) << ": the work list is not the drawing polygons' runs";
    EXPECT_EQ(varied, expected_varied) << density_path_name(path) << ": the varying polygons' list is not their runs";
    const std::vector<uint32_t> ring = read_splat_list(context, object.frame.splat_ring, "ring list");
    std::vector<uint32_t> all = listed;
    all.insert(all.end(), varied.begin(), varied.end());
    std::sort(all.begin(), all.end());
    EXPECT_TRUE(std::includes(all.begin(), all.end(), ring.begin(), ring.end())) << "the ring list holds other items";
    EXPECT_EQ(std::adjacent_find(ring.begin(), ring.end()), ring.end()) << "an item is in the ring list twice";
    std::printf("%s: %zu work items, %zu of polygons whose density varies, %zu astride the outline\n",
                density_path_name(path), listed.size(), varied.size(), ring.size());
}

struct PathFrames {
    std::vector<RenderedFrame> frames;
    std::vector<std::vector<uint32_t>> masks;
    uint32_t cpu_listed = 0, gpu_listed = 0;  // the survivors' lists of the cpu and indirect paths
    uint32_t band = 0;  // stipples of polygons large on screen whose index lies between their least and most density
    uint32_t chunks = 0;  // the vertex path's chunks of the polygons whose density changes across them
};

// The vertex path's second draw (GradientChunks): an instance of kGradientChunk candidates for each chunk of
// each drawing polygon whose density changes across it, up to the most density any of them sees, and
// nothing else (the first draw culls those polygons' candidates).
uint32_t expect_gradient_chunks(const gpu::Context& context, StippleRenderer& renderer, const StippleSet& stipples) {
    const std::vector<std::byte> bytes = gpu::read_buffer(context, renderer.object(0).frame.drawn_stipples);
    gpu::DrawCommand draw;
    std::memcpy(&draw, bytes.data(), sizeof draw);
    EXPECT_EQ(draw.vertex_count, gpu::kGradientChunk);
    EXPECT_EQ(draw.first_vertex, 0u);
    EXPECT_EQ(draw.first_instance, 0u);
    std::vector<uint32_t> listed(draw.instance_count);
    std::memcpy(listed.data(), bytes.data() + sizeof draw, sizeof(uint32_t) * listed.size());
    std::sort(listed.begin(), listed.end());
    const std::vector<float> densities = renderer.read_densities(0);
    const std::vector<glm::vec2> bounds = renderer.read_density_bounds(0);
    std::vector<uint32_t> expected;
    for (uint32_t t = 0; t < densities.size(); ++t) {
        if (!(densities[t] > 0.0f) || bounds[t].x == bounds[t].y) continue;
        const uint32_t drawn = formulas::drawn_stipple_count(bounds[t].y, stipples.first[t + 1] - stipples.first[t]);
        for (uint32_t k = 0; k < drawn; k += gpu::kGradientChunk) expected.push_back(stipples.first[t] + k);
    }
    EXPECT_EQ(listed, expected) << "the vertex path's chunks are not those of the polygons whose density varies";
    return draw.instance_count;
}

// Every density path draws the subject; the masks and images must agree (checked by the caller).
PathFrames draw_with_every_path(const gpu::Context& context, const test::Prepared& subject, const ObjectParams& params,
                                float distance, bool scalar_texels = false, bool orthographic = false) {
    RendererOptions options;
    options.count_drawn = true;
    options.scalar_texels = scalar_texels;
    StippleRenderer renderer(context, kColorFormat, context.depth_format, options);
    renderer.add_object(subject.mesh, subject.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(context, {1280, 1024});
    FrameView view = test::framed_view(compute_bounding_sphere(subject.mesh), target.extent(), distance, 20.0f, 10.0f, orthographic);
    PathFrames out;
    for (DensityPath path : kAllDensityPaths) {
        renderer.params(0).density_path = path;
        out.frames.push_back(target.render(renderer, view));
        out.masks.push_back(renderer.drawn_mask(0));
        if (path == DensityPath::Cpu || path == DensityPath::Indirect) {
            // The list's draw command: vertex_count survivors, then their indices, each drawn once.
            const std::vector<std::byte> bytes = gpu::read_buffer(context, renderer.object(0).frame.drawn_stipples);
            gpu::DrawCommand draw;
            std::memcpy(&draw, bytes.data(), sizeof draw);
            std::vector<uint32_t> listed(draw.vertex_count);
            std::memcpy(listed.data(), bytes.data() + sizeof draw, sizeof(uint32_t) * listed.size());
            std::sort(listed.begin(), listed.end());
            EXPECT_EQ(std::adjacent_find(listed.begin(), listed.end()), listed.end()) << "a stipple listed twice";
            EXPECT_EQ(draw.instance_count, 1u);
            (path == DensityPath::Cpu ? out.cpu_listed : out.gpu_listed) = draw.vertex_count;
            // Each drawing polygon's candidates up to the most density any of them sees.
            const std::vector<float> densities = renderer.read_densities(0);
            const std::vector<glm::vec2> bounds = renderer.read_density_bounds(0);
            uint32_t expected = 0, band = 0;
            for (size_t t = 0; t < densities.size(); ++t) {
                if (!(densities[t] > 0.0f)) continue;
                const uint32_t candidates = subject.stipples.first[t + 1] - subject.stipples.first[t];
                expected += formulas::drawn_stipple_count(bounds[t].y, candidates);
                band += formulas::drawn_stipple_count(bounds[t].y, candidates) -
                        std::min(uint32_t(std::floor(bounds[t].x)), candidates);
            }
            EXPECT_EQ(draw.vertex_count, expected) << density_path_name(path);
            out.band = std::max(out.band, band);
        }
        if (draws_by_splat(path)) expect_splat_work_list(context, renderer, subject.stipples, path);
        if (path == DensityPath::Vertex) out.chunks = expect_gradient_chunks(context, renderer, subject.stipples);
        std::printf("%-8s path: %lld stipples drawn\n", density_path_name(path),
                    (long long)renderer.stats().drawn_stipples);
        EXPECT_EQ(size_t(renderer.stats().drawn_stipples), test::popcount(out.masks.back()));
    }
    return out;
}

void expect_same_stipples_and_images(const PathFrames& out) {
    for (size_t i = 1; i < out.masks.size(); ++i) {
        DensityPath path = kAllDensityPaths[i];
        EXPECT_EQ(out.masks[i], out.masks[0]) << density_path_name(path) << " drew a different set of stipples";
        // The rasterising paths blend in the same order; the compute splat composites in float and
        // rounds once, so its pixels may differ from blending's 8-bit steps by a level or two.
        bool splat = draws_by_splat(path);
        double differing = fraction_differing(out.frames[0].color, out.frames[i].color, splat ? 2 : 0);
        std::printf("%s path: %.4f%% of pixels differ from the vertex path\n", density_path_name(path),
                    100.0 * differing);
        EXPECT_LE(differing, splat ? 0.01 : 0.001);
    }
}

TEST_F(DensityPaths, AllPathsDrawExactlyTheSameStipples) {
    ObjectParams params;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    PathFrames out = draw_with_every_path(*context, blob, params, 1.5f);
    std::printf("survivors listed: %u by the CPU path, %u by the indirect path; %u drawn (%u in the band where a "
                "large polygon's density decides per stipple); %u chunks of such polygons drawn by the vertex path's "
                "second draw\n",
                out.cpu_listed, out.gpu_listed, uint32_t(test::popcount(out.masks[0])), out.band, out.chunks);
    // Every drawn stipple, and besides them only stipples of the band (culled by the vertex shader).
    for (uint32_t listed : {out.cpu_listed, out.gpu_listed}) {
        EXPECT_GE(listed, test::popcount(out.masks[0]));
        EXPECT_LE(listed, test::popcount(out.masks[0]) + out.band);
    }
    EXPECT_GT(test::popcount(out.masks[0]), 10000u);
    EXPECT_LT(test::popcount(out.masks[0]), blob.stipples.size());
    expect_same_stipples_and_images(out);
}

// An orthographic view (parallel lines of sight): the CPU's densities, the density pass and every path's culling
// read the eye ray and the scale from the projection alike, and draw the same stipples. Close enough that large
// polygons carry their density across them.
TEST_F(DensityPaths, AllPathsDrawTheSameStipplesInAnOrthographicView) {
    ObjectParams params;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    PathFrames out = draw_with_every_path(*context, blob, params, 0.6f, false, true);
    std::printf("orthographic: %u drawn, %u in the band of large polygons\n", uint32_t(test::popcount(out.masks[0])), out.band);
    EXPECT_GT(test::popcount(out.masks[0]), 10000u);
    EXPECT_GT(out.band, 0u) << "no polygon carries its density across it: the test misses that part";
    expect_same_stipples_and_images(out);
}

// Close up, the polygons beyond the frame's edges and behind the eye draw nothing (kFlagCullOutsideView):
// every path draws the same image as with them, from a fraction of the stipples, and the paths still agree.
TEST_F(DensityPaths, PolygonsOutsideTheViewDrawNothingAndTheImageStays) {
    ObjectParams params;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
    renderer.add_object(blob.mesh, blob.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {640, 512});
    for (const float distance : {0.35f, 0.12f}) {
        FrameView view = test::framed_view(compute_bounding_sphere(blob.mesh), target.extent(), distance);
        for (DensityPath path : kAllDensityPaths) {
            renderer.params(0).density_path = path;
            view.cull_outside_view = false;
            const RenderedFrame all = target.render(renderer, view);
            const std::vector<uint32_t> all_mask = renderer.drawn_mask(0);
            view.cull_outside_view = true;
            const RenderedFrame culled = target.render(renderer, view);
            const std::vector<uint32_t> culled_mask = renderer.drawn_mask(0);
            const size_t n_all = test::popcount(all_mask), n_culled = test::popcount(culled_mask);
            std::printf("distance %.2f, %-9s path: %zu stipples drawn, %zu with the polygons outside the view culled\n", distance,
                        density_path_name(path), n_all, n_culled);
            EXPECT_EQ(fraction_differing(all.color, culled.color, 0), 0.0) << density_path_name(path) << ": the image changed";
            for (size_t w = 0; w < all_mask.size(); ++w)
                EXPECT_EQ(culled_mask[w] & ~all_mask[w], 0u) << "a stipple drawn only with culling, word " << w;
            EXPECT_GT(n_all, 2000u);
            EXPECT_LT(double(n_culled), 0.6 * double(n_all)) << density_path_name(path);
        }
    }
    // The paths cull alike (the CPU's densities follow the same test), and draw the same ink: close up the
    // dots are enlarged, and the points pipeline pulls them onto their slanted surface as the splat does
    // (until 2026-12-05 it pulled round points only, and read 16.8% of ink here against the splat's 19.4%).
    const PathFrames close = draw_with_every_path(*context, blob, params, 0.35f);
    for (size_t i = 1; i < close.masks.size(); ++i) {
        EXPECT_EQ(close.masks[i], close.masks[0]) << density_path_name(kAllDensityPaths[i]) << " drew a different set of stipples";
        const double ink = test::mean_ink(close.frames[i]), vertex = test::mean_ink(close.frames[0]);
        std::printf("close up, %s path: mean ink %.4f (vertex %.4f)\n", density_path_name(kAllDensityPaths[i]), ink, vertex);
        EXPECT_NEAR(ink, vertex, 0.03 * vertex) << density_path_name(kAllDensityPaths[i]);
    }
}

// The dots astride the outline of an object small on screen (kOutlineShiftBelowPx): the points paths move them
// onto the surface (stipple.vert, outline_shift), as the splat inks their pixels beyond the outline beside them.
// Clipped there, they left the outline band lighter, a share of the footprint that grows as the object shrinks.
// The same stipples are drawn either way; where the frame's depth words do not fit one buffer, the points are
// drawn as before (placeholders bound in their place).
TEST_F(DensityPaths, PointsMoveTheirDotsAstrideASmallObjectsOutlineOntoIt) {
    ObjectParams params;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
    renderer.add_object(blob.mesh, blob.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {1600, 1280});
    const DensityPath paths[] = {DensityPath::Splat, DensityPath::Vertex, DensityPath::Cpu, DensityPath::Indirect};
    double splat = 0.0, vertex = 0.0, before = 0.0;  // mean ink summed over views all around, 64 px high
    size_t drawn = 0;
    for (float yaw = 0.0f; yaw < 360.0f; yaw += 45.0f) {
        const FrameView view = test::framed_view(compute_bounding_sphere(blob.mesh), target.extent(), 20.0f, yaw);
        std::vector<RenderedFrame> frames;
        std::vector<std::vector<uint32_t>> masks;
        for (DensityPath path : paths) {
            renderer.params(0).density_path = path;
            frames.push_back(target.render(renderer, view));
            masks.push_back(renderer.drawn_mask(0));
        }
        {
            test::ScopedEnv small("STIPPLE_MAX_STORAGE_BUFFER", "6M");  // the frame's 7.8 MiB of words do not fit
            renderer.params(0).density_path = DensityPath::Vertex;
            before += test::mean_ink(target.render(renderer, view));
            EXPECT_EQ(renderer.drawn_mask(0), masks[1]) << "yaw " << yaw;
        }
        splat += test::mean_ink(frames[0]);
        vertex += test::mean_ink(frames[1]);
        drawn += test::popcount(masks[0]);
        for (size_t i = 1; i < masks.size(); ++i) EXPECT_EQ(masks[i], masks[0]) << density_path_name(paths[i]) << ", yaw " << yaw;
        // The list paths draw with the same vertex shader variant: the same pixels.
        for (size_t i = 2; i < frames.size(); ++i)
            EXPECT_EQ(fraction_differing(frames[1].color, frames[i].color, 0), 0.0) << density_path_name(paths[i]);
    }
    std::printf("%zu stipples drawn in 8 views; mean ink: splat %.4f, vertex %.4f, vertex with its outline dots clipped "
                "%.4f\n", drawn, splat / 8.0, vertex / 8.0, before / 8.0);
    EXPECT_GT(drawn, 1000u);
    // A whole-pixel move keeps fewer of the lost pixels than the splat's ring where a dot cannot move whole onto
    // visible surface (thin parts, steep sides).
    EXPECT_LT(std::abs(vertex - splat), 0.5 * std::abs(before - splat)) << "the outline's dots were not moved";
    EXPECT_GT(vertex, before);
}

// Dots above 2.5 px are discs (round points; the splat's kSpecRoundPoints variant). On a flat disc
// facing the eye (no pixel of a dot hidden by its own surface's curvature), the splat inks as many
// pixels per drawn dot as the rasteriser's round points do; squares would ink about a fifth more.
TEST_F(DensityPaths, TheSplatDrawsLargeDotsAsDiscs) {
    ObjectParams params;
    params.point_size = 6.0f;
    params.generation.dmax = 0.01f;
    params.shading = false;
    Prepared disc = test::prepare(test::make_disc(64, 16), params);
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
    renderer.add_object(disc.mesh, disc.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {640, 512});
    const FrameView view = test::framed_view(compute_bounding_sphere(disc.mesh), target.extent(), 1.0f, 0.0f, 0.0f);
    double per_dot[2] = {0.0, 0.0};
    const DensityPath paths[2] = {DensityPath::Vertex, DensityPath::Splat};
    for (int i = 0; i < 2; ++i) {
        renderer.params(0).density_path = paths[i];
        const RenderedFrame frame = target.render(renderer, view);
        size_t inked = 0;
        for (size_t p = 0; p < frame.depth.size(); ++p) inked += frame.color.pixels[4 * p] < 128;
        const double drawn = double(renderer.stats().drawn_stipples);
        ASSERT_GT(drawn, 1000.0);
        per_dot[i] = double(inked) / drawn;
        std::printf("%s path: %.0f dots, %.2f inked pixels each\n", density_path_name(paths[i]), drawn, per_dot[i]);
    }
    EXPECT_NEAR(per_dot[1] / per_dot[0], 1.0, 0.03);
}

TEST_F(DensityPaths, TheSplatsLargeDotsComposeAsThePointsBlend) {
    // Large dots at a low density on a curved surface: most drawn stipples are a polygon's fractional
    // last one (§2.1), and 6-px dots at D_max 0.02 overlap more often than not. The points pipeline
    // blends the overlaps (1 - (1 - a)(1 - b)); a splat that kept only the strongest dot of each pixel
    // read a third lighter (mean ink 0.131 against 0.196) with a quarter of the pixels darker than half.
    ObjectParams params;
    params.point_size = 6.0f;
    params.generation.dmax = 0.02f;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(blob.mesh, blob.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {640, 512});
    const FrameView view = test::framed_view(compute_bounding_sphere(blob.mesh), target.extent(), 1.0f, 30.0f, 15.0f);
    // Small square dots first: the renderer holds no cover sums until a frame draws large dots.
    renderer.params(0).point_size = 1.5f;
    renderer.params(0).density_path = DensityPath::Splat;
    const double small_ink = test::mean_ink(target.render(renderer, view));
    renderer.params(0).point_size = 6.0f;
    double dark[2] = {0.0, 0.0}, ink[2] = {0.0, 0.0};
    const DensityPath paths[2] = {DensityPath::Vertex, DensityPath::Splat};
    for (int i = 0; i < 2; ++i) {
        renderer.params(0).density_path = paths[i];
        const RenderedFrame frame = target.render(renderer, view);
        for (size_t p = 0; p < frame.depth.size(); ++p) dark[i] += frame.color.pixels[4 * p] < 128;
        ink[i] = test::mean_ink(frame);
        std::printf("%s path: %.0f pixels darker than half, mean ink %.4f\n", density_path_name(paths[i]), dark[i],
                    ink[i]);
    }
    ASSERT_GT(dark[0], 5000.0);
    EXPECT_LT(small_ink, 0.5 * ink[1]);
    EXPECT_NEAR(dark[1] / dark[0], 1.0, 0.02);
    EXPECT_NEAR(ink[1] / ink[0], 1.0, 0.02);
}

TEST_F(DensityPaths, EveryPathReadsTheMeshAlikeAFloatOrAVertexPerTexel) {
    // The stipple shaders read the polygons' corners from texel buffers (shaders/stipple_position.h):
    // a vertex per texel, or a float per texel on devices without three-component texel buffers.
    // Both layouts must place the same stipples.
    ObjectParams params;
    Prepared blob = test::prepare(load_mesh(blobby_path()), params);
    const PathFrames vec3 = draw_with_every_path(*context, blob, params, 1.5f);
    const PathFrames scalar = draw_with_every_path(*context, blob, params, 1.5f, true);
    for (size_t i = 0; i < vec3.masks.size(); ++i) {
        const DensityPath path = kAllDensityPaths[i];
        EXPECT_EQ(scalar.masks[i], vec3.masks[i]) << density_path_name(path);
        const double differing = fraction_differing(vec3.frames[i].color, scalar.frames[i].color, 0);
        std::printf("%s path: %.4f%% of pixels differ between the texel layouts\n", density_path_name(path),
                    100.0 * differing);
        EXPECT_LE(differing, 0.001) << density_path_name(path);
    }
    EXPECT_GT(test::mean_ink(scalar.frames[0]), 0.05);
}

// The most stipples one polygon draws, from a drawn-stipple mask.
size_t most_drawn_by_one_polygon(const StippleSet& stipples, const std::vector<uint32_t>& mask) {
    size_t most = 0;
    for (size_t t = 0; t + 1 < stipples.first.size(); ++t) {
        size_t drawn = 0;
        for (uint32_t i = stipples.first[t]; i < stipples.first[t + 1]; ++i) drawn += (mask[i >> 5] >> (i & 31)) & 1u;
        most = std::max(most, drawn);
    }
    return most;
}

TEST_F(DensityPaths, AllPathsDrawEveryStippleOfLargePolygons) {
    // A framed 12-triangle box draws thousands of stipples per polygon. One splat invocation per
    // polygon inked only the first ~3,500 of them on lavapipe (its loop limit, see kSplatChunk): the
    // box read 0.08 ink instead of 0.27.
    ObjectParams params;
    Prepared box = test::prepare(make_box(), params);
    PathFrames out = draw_with_every_path(*context, box, params, 1.0f);
    const size_t most = most_drawn_by_one_polygon(box.stipples, out.masks[0]);
    std::printf("box: %zu stipples drawn, at most %zu by one polygon\n", test::popcount(out.masks[0]), most);
    EXPECT_GT(most, 20 * size_t(gpu::kSplatChunk)) << "the box should draw many work items per polygon";
    // Its faces' density changes across them: the vertex path draws them by its second, chunked draw.
    EXPECT_GT(out.chunks, 20u);
    expect_same_stipples_and_images(out);
    EXPECT_NEAR(test::mean_ink(out.frames.back()), test::mean_ink(out.frames[0]), 0.02 * test::mean_ink(out.frames[0]));
}

TEST_F(DensityPaths, AllPathsListEveryStippleOfAPolygonDrawingMoreThanALoopAllows) {
    // Without the distance enhancement the framed box draws every candidate of its front faces, some
    // 68,000 a polygon. The indirect path listed them with one invocation per polygon, which lavapipe ends
    // after 65535 loop iterations: it drew 151,822 stipples where the others drew 157,284 (seen in a
    // parity run against an NVIDIA GPU). It now lists from the density pass's work items.
    ObjectParams params;
    params.extrinsic = false;
    params.intrinsic = false;
    params.shading = false;
    Prepared box = test::prepare(make_box(), params);
    PathFrames out = draw_with_every_path(*context, box, params, 1.0f);
    const size_t most = most_drawn_by_one_polygon(box.stipples, out.masks[0]);
    std::printf("box without enhancements: %zu stipples drawn, at most %zu by one polygon\n",
                test::popcount(out.masks[0]), most);
    EXPECT_GT(most, 65535u) << "a polygon should draw more stipples than one invocation may loop over";
    expect_same_stipples_and_images(out);
}

TEST_F(DensityPaths, AllPathsDrawEveryLargeDotOfLargePolygons) {
    // 32-px dots on the framed box, its polygons drawing dozens each: runs of 64 such dots (1,089 pixel
    // iterations each) passed lavapipe's loop limit, and the splat drew 127 of the 596 stipples the
    // points pipeline drew (10.2% ink against 45.6%). Runs are now cut to fit (splat_run_length).
    ObjectParams params;
    params.point_size = 32.0f;
    params.generation.dmax = 0.002f;
    Prepared box = test::prepare(make_box(), params);
    PathFrames out = draw_with_every_path(*context, box, params, 1.0f);
    const size_t most = most_drawn_by_one_polygon(box.stipples, out.masks[0]);
    std::printf("box, 32-px dots: %zu stipples drawn, at most %zu by one polygon\n", test::popcount(out.masks[0]), most);
    EXPECT_GT(most, size_t(gpu::kSplatChunk)) << "some polygon should draw more than one run of the old length";
    for (size_t i = 1; i < out.masks.size(); ++i) {
        EXPECT_EQ(out.masks[i], out.masks[0]) << density_path_name(kAllDensityPaths[i]) << " drew a different set";
        const double ink = test::mean_ink(out.frames[i]), vertex = test::mean_ink(out.frames[0]);
        std::printf("%s path: mean ink %.4f (vertex %.4f)\n", density_path_name(kAllDensityPaths[i]), ink, vertex);
        EXPECT_NEAR(ink, vertex, 0.02 * vertex) << density_path_name(kAllDensityPaths[i]);
    }
}

// A large dot is drawn flat at its centre's depth while its face slants away: half of a 32-px disc fell
// behind its own surface (cut circles, 443 inked pixels a dot on this view against 754 now), on every path.
// large_dot_depth_pull keeps the whole disc on its face; few dots, so that they seldom overlap.
TEST_F(DensityPaths, LargeDotsOnSlantedFacesAreWholeDiscs) {
    ObjectParams params;
    params.point_size = 32.0f;
    params.generation.dmax = 0.0004f;
    Prepared box = test::prepare(make_box(), params);
    RendererOptions options;
    options.count_drawn = true;
    StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
    renderer.add_object(box.mesh, box.stipples, glm::mat4(1.0f), params);
    OffscreenTarget target(*context, {1280, 1024});
    const FrameView view = test::framed_view(compute_bounding_sphere(box.mesh), target.extent(), 1.0f, 35.0f, 25.0f);
    const double disc = 32.0 * 32.0;  // a round dot inks its point size squared (drawn_point_size)
    for (DensityPath path : {DensityPath::Vertex, DensityPath::Splat}) {
        renderer.params(0).density_path = path;
        const RenderedFrame frame = target.render(renderer, view);
        size_t dark = 0;
        for (size_t i = 0; i < frame.color.pixels.size(); i += 4) dark += frame.color.pixels[i] < 128;
        const double drawn = double(renderer.stats().drawn_stipples);
        std::printf("%s path: %.0f dots, %.0f dark pixels a dot (a disc: %.0f)\n", density_path_name(path), drawn,
                    double(dark) / drawn, disc);
        ASSERT_GT(drawn, 50.0);
        EXPECT_GT(double(dark) / drawn, 0.85 * disc) << density_path_name(path) << ": dots cut by their own face";
    }
}

}  // namespace
}  // namespace stipple
