// The depth pass's triangle list (render/depth_triangles.hpp): drawing only the triangles that may
// cover a pixel centre changes nothing in the image (colour, depth and so the stencil-masked ink) on
// every kind of object, while it leaves most of a fine mesh's triangles out when they are small.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "anim/procedural_rigs.hpp"
#include "mesh/primitives.hpp"
#include "render/tiled_render.hpp"
#include "stipple/object_data.hpp"
#include "support/anim_files.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

class DepthTriangles : public test::GpuTest {};

constexpr VkExtent2D kExtent{320, 256};

struct Drawn {
    RenderedFrame frame;
    uint32_t depth_triangles = 0;  // what the depth pass drew
    bool listed = false;
};

Drawn draw(gpu::Context& context, const test::Prepared& object, const ObjectParams& params, const FrameView& view,
           DepthCull mode) {
    RendererOptions options;
    options.depth_cull = mode;
    options.depth_raster = DepthRaster::Fixed;  // the lists are the fixed-function pass's
    StippleRenderer renderer(context, kColorFormat, context.depth_format, options);
    renderer.add_object(object.mesh, object.stipples, object.model, params);
    OffscreenTarget target(context, view.extent);
    Drawn d;
    d.frame = target.render(renderer, view);
    d.depth_triangles = renderer.read_depth_triangles(0);
    d.listed = renderer.object(0).frame.depth_listed;
    return d;
}

size_t differing_pixels(const RenderedFrame& a, const RenderedFrame& b) {
    size_t differ = 0;
    for (size_t i = 0; i < a.depth.size(); ++i)
        differ += a.depth[i] != b.depth[i] || std::memcmp(&a.color.pixels[4 * i], &b.color.pixels[4 * i], 4) != 0;
    return differ;
}

// A 100k-triangle sphere at a quarter of the framing size: its triangles average ~0.15 px on screen.
TEST_F(DepthTriangles, SameImageWithAFractionOfTheTriangles) {
    ObjectParams params;
    const test::Prepared sphere = test::prepare(make_uv_sphere(100000), params);
    const FrameView far = test::framed_view(compute_bounding_sphere(sphere.mesh), kExtent, 4.0f);
    const Drawn all = draw(*context, sphere, params, far, DepthCull::Off);
    const Drawn listed = draw(*context, sphere, params, far, DepthCull::On);
    const uint32_t triangles = uint32_t(sphere.mesh.triangle_count());
    EXPECT_FALSE(all.listed);
    EXPECT_EQ(all.depth_triangles, triangles);
    ASSERT_TRUE(listed.listed);
    // Half face away; of the rest, about one in six covers a pixel centre at this size.
    EXPECT_LT(listed.depth_triangles, triangles / 4) << "of " << triangles;
    EXPECT_GT(listed.depth_triangles, 0u);
    EXPECT_GT(test::measure_ink(all.frame).covered, 1000u);
    EXPECT_EQ(differing_pixels(all.frame, listed.frame), 0u);
}

// Framed, most triangles cover pixels: the list keeps them, and leaves the faces facing away to the
// cull, on every density path and with lines (object-space lines on an open mesh keep those faces).
TEST_F(DepthTriangles, SameImageFramedWithLinesAndOnEveryPath) {
    ObjectParams plain;
    plain.silhouette_lines = true;
    const test::Prepared sphere = test::prepare(make_uv_sphere(20000), plain);
    const FrameView framed = test::framed_view(compute_bounding_sphere(sphere.mesh), kExtent);
    std::vector<ObjectParams> variants;
    for (DensityPath path : {DensityPath::Splat, DensityPath::Vertex, DensityPath::Cpu}) {
        ObjectParams p = plain;
        p.density_path = path;
        variants.push_back(p);
    }
    ObjectParams lines = plain;
    lines.contours = lines.creases = true;
    variants.push_back(lines);
    for (const ObjectParams& params : variants) {
        const std::string what = std::string(density_path_name(params.density_path)) + (params.contours ? " + lines" : "");
        const Drawn all = draw(*context, sphere, params, framed, DepthCull::Off);
        const Drawn listed = draw(*context, sphere, params, framed, DepthCull::On);
        ASSERT_TRUE(listed.listed) << what;
        if (!params.contours) {
            EXPECT_LT(listed.depth_triangles, sphere.mesh.triangle_count() * 6 / 10) << what;
        }
        EXPECT_EQ(differing_pixels(all.frame, listed.frame), 0u) << what;
    }
}

// An open bowl seen from above: its inside (faces facing away) shows through the opening, so its depth
// pass keeps those faces, and so must the list.
TEST_F(DepthTriangles, KeepsFacesAwayWhereTheyCanBeSeen) {
    ObjectParams params;
    params.two_sided = true;
    const test::Prepared bowl = test::prepare(test::make_open_hemisphere(256, 128), params);
    const FrameView above = test::framed_view(compute_bounding_sphere(bowl.mesh), kExtent, 3.0f, 25.0f, 55.0f);
    const Drawn all = draw(*context, bowl, params, above, DepthCull::Off);
    const Drawn listed = draw(*context, bowl, params, above, DepthCull::On);
    ASSERT_TRUE(listed.listed);
    EXPECT_LT(listed.depth_triangles, bowl.mesh.triangle_count() / 2);
    EXPECT_EQ(differing_pixels(all.frame, listed.frame), 0u);
    // One-sided, the inside of the open bowl carries no stipples but still hides what lies behind it: listed alike.
    params.two_sided = false;
    const Drawn one_sided = draw(*context, bowl, params, above, DepthCull::On);
    EXPECT_EQ(one_sided.depth_triangles, listed.depth_triangles);
    // Where the faces away can never be seen (a surface its loading found closed), the list leaves them out.
    test::Prepared closed = bowl;
    closed.mesh.winding.parts = 1;
    closed.mesh.winding.border_edges = 0;
    const Drawn culled = draw(*context, closed, params, above, DepthCull::On);
    EXPECT_LT(culled.depth_triangles, listed.depth_triangles);
}

// Print tiles: each tile lists against its own viewport and projection.
TEST_F(DepthTriangles, TilesListAgainstTheirOwnViewport) {
    ObjectParams params;
    const test::Prepared sphere = test::prepare(make_uv_sphere(100000), params);
    const FrameView far = test::framed_view(compute_bounding_sphere(sphere.mesh), kExtent, 3.0f);
    Image tiled[2];
    for (DepthCull mode : {DepthCull::Off, DepthCull::On}) {
        RendererOptions options;
        options.depth_cull = mode;
        options.depth_raster = DepthRaster::Fixed;  // the lists are the fixed-function pass's
        StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
        renderer.add_object(sphere.mesh, sphere.stipples, sphere.model, params);
        tiled[mode == DepthCull::On] = render_tiled(*context, renderer, far, 96);
        EXPECT_EQ(renderer.object(0).frame.depth_listed, mode == DepthCull::On);
    }
    EXPECT_EQ(tiled[0].pixels, tiled[1].pixels);
}

// An animated object lists its deformed triangles (the deformation pass runs first).
TEST_F(DepthTriangles, AnimatedObjectsListTheirPose) {
    anim::rigs::CylinderOptions rig;
    rig.rings = 96;
    rig.segments = 160;
    const std::string path = test::write_rig(anim::rigs::bending_cylinder(rig), "depth_triangles", "cylinder");
    const ObjectData model = load_model_data(path);
    const auto stipples = make_stipples(model, ObjectParams{}.generation, StippleSource::Generate);
    const FrameView far = test::framed_view(model.bounds, kExtent, 3.0f);
    std::vector<RenderedFrame> frames;
    for (DepthCull mode : {DepthCull::Off, DepthCull::On}) {
        RendererOptions options;
        options.depth_cull = mode;
        options.depth_raster = DepthRaster::Fixed;  // the lists are the fixed-function pass's
        StippleRenderer renderer(*context, kColorFormat, context->depth_format, options);
        renderer.add_object(*model.mesh, *stipples, glm::mat4(1.0f), ObjectParams{}, model.motion);
        renderer.set_animation(0, 0, 1.0);  // bent by 90 degrees
        OffscreenTarget target(*context, kExtent);
        frames.push_back(target.render(renderer, far));
        if (mode == DepthCull::On) {
            EXPECT_LT(renderer.read_depth_triangles(0), model.mesh->triangle_count() / 2);
        }
    }
    EXPECT_EQ(differing_pixels(frames[0], frames[1]), 0u);
}

// auto lists a fine mesh far away and draws a coarse or near one whole; toon objects never list.
TEST_F(DepthTriangles, AutoListsOnlySmallTriangles) {
    ObjectParams params;
    const test::Prepared fine = test::prepare(make_uv_sphere(100000), params);
    const Sphere bounds = compute_bounding_sphere(fine.mesh);
    EXPECT_TRUE(draw(*context, fine, params, test::framed_view(bounds, kExtent, 4.0f), DepthCull::Auto).listed);
    EXPECT_FALSE(draw(*context, fine, params, test::framed_view(bounds, kExtent, 0.5f), DepthCull::Auto).listed);
    const test::Prepared coarse = test::prepare(make_uv_sphere(2000), params);
    EXPECT_FALSE(draw(*context, coarse, params, test::framed_view(bounds, kExtent, 4.0f), DepthCull::Auto).listed);
    params.toon = true;
    EXPECT_FALSE(draw(*context, fine, params, test::framed_view(bounds, kExtent, 4.0f), DepthCull::On).listed);
}

// The chooser's rounds, fed with made-up timings: it keeps the faster, times again after its hold or
// when the scale changes, and forgets when nothing is to be listed.
int frames_listed(DepthCullChooser& chooser, float px, int frames, double whole_ms, double listed_ms) {
    int listed = 0;
    for (int i = 0; i < frames; ++i) {
        const bool list = chooser.next_frame(px);
        listed += list;
        chooser.frame_done(list ? listed_ms : whole_ms);
    }
    return listed;
}

TEST(DepthCullChooser, KeepsTheFasterAfterTimingBoth) {
    DepthCullChooser chooser;
    // Small triangles: the guess lists first; the frames say the whole draw is faster.
    EXPECT_TRUE(chooser.next_frame(0.3f));
    chooser.frame_done(10.0);  // untimed
    const int round = kDepthCullTimedFrames;
    EXPECT_EQ(frames_listed(chooser, 0.3f, round, 20.0, 30.0), round / 2);
    EXPECT_EQ(frames_listed(chooser, 0.3f, kDepthCullHoldFrames - 1, 20.0, 30.0), 0);
    // After the hold it times both again, and now the list is faster.
    EXPECT_EQ(frames_listed(chooser, 0.3f, round + 1, 30.0, 20.0), round / 2 + 1);
    EXPECT_EQ(frames_listed(chooser, 0.3f, 50, 30.0, 20.0), 50);
    // The scale changes by more than half: a new round, starting from the new guess (whole at 1.5 px).
    EXPECT_FALSE(chooser.next_frame(1.5f));
    chooser.frame_done(30.0);
    EXPECT_EQ(frames_listed(chooser, 1.5f, round, 30.0, 20.0), round / 2);
    EXPECT_EQ(frames_listed(chooser, 1.5f, 20, 30.0, 20.0), 20);
    // Nothing to list: no list, and a fresh round once something is.
    EXPECT_FALSE(chooser.next_frame(0.0f));
    EXPECT_FALSE(chooser.next_frame(1.5f));  // the guess again
    // One slow frame does not decide: the fastest of each is compared.
    DepthCullChooser noisy;
    noisy.next_frame(0.5f);
    noisy.frame_done(100.0);
    double listed_times[] = {15.0, 40.0, 16.0};
    double whole_times[] = {18.0, 19.0, 17.5};
    for (int i = 0; i < round; ++i) {
        const bool list = noisy.next_frame(0.5f);
        noisy.frame_done(list ? listed_times[i / 2] : whole_times[i / 2]);
    }
    EXPECT_TRUE(noisy.next_frame(0.5f));
}

}  // namespace
}  // namespace stipple
