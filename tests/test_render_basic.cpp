// Offscreen rendering on the Vulkan device (lavapipe in CI): ink where the model is and nowhere
// else, and hidden-stipple removal through the depth pass (paper §2.1).
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "mesh/load_mesh.hpp"
#include "mesh/primitives.hpp"
#include "support/gpu_test.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class RenderBasics : public test::GpuTest {};

struct Prepared {
    Mesh mesh;
    StippleSet stipples;
    glm::mat4 model{1.0f};
};

Prepared prepare(Mesh mesh, const ObjectParams& params, glm::mat4 model = glm::mat4(1.0f)) {
    Prepared p;
    p.stipples = generate_stipples(mesh, params.generation);
    p.mesh = std::move(mesh);
    p.model = model;
    return p;
}

RenderedFrame render(gpu::Context& context, const std::vector<const Prepared*>& objects, const ObjectParams& params,
                     const Sphere& frame_on, VkExtent2D extent = {640, 512}) {
    StippleRenderer renderer(context, kColorFormat, context.depth_format);
    for (const Prepared* p : objects) renderer.add_object(p->mesh, p->stipples, p->model, params);
    OffscreenTarget target(context, extent);
    float aspect = float(extent.width) / float(extent.height);
    FrameView view;
    view.camera = camera_matrices(frame_sphere(frame_on, aspect, 1.0f, 20.0f, 10.0f), aspect, frame_on);
    return target.render(renderer, view);
}

// The unit sphere at the origin, framed as render() frames its objects.
FrameView unit_sphere_view(VkExtent2D extent) {
    const Sphere frame_on{glm::vec3(0.0f), 1.0f};
    const float aspect = float(extent.width) / float(extent.height);
    FrameView view;
    view.camera = camera_matrices(frame_sphere(frame_on, aspect, 1.0f, 20.0f, 10.0f), aspect, frame_on);
    return view;
}

TEST_F(RenderBasics, BunnyInkStaysInsideTheFootprint) {
    std::string path = test::shared_model("stanford-bunny.obj");
    if (path.empty()) GTEST_SKIP() << "../shared/models/stanford-bunny.obj is absent";
    ObjectParams params;
    Prepared bunny = prepare(load_mesh(path), params);
    Sphere sphere = compute_bounding_sphere(bunny.mesh);
    RenderedFrame frame = render(*context, {&bunny}, params, sphere, {1280, 1024});
    write_png(test::output_path("bunny_default.png").string(), frame.color);

    test::InkFigures ink = test::measure_ink(frame);
    std::printf("bunny 1280x1024: covered %zu px, ink inside %.1f%%, non-white outside %zu px\n", ink.covered,
                100.0 * ink.ink_fraction(), ink.non_white_outside);
    EXPECT_GT(ink.covered, 100000u);
    EXPECT_GE(ink.ink_fraction(), 0.03);
    EXPECT_LE(ink.ink_fraction(), 0.40);
    EXPECT_EQ(ink.non_white_outside, 0u) << "background must stay pure white outside the footprint";
}

TEST_F(RenderBasics, SphereInkOnlyOnVisibleSideAndBackgroundPureWhite) {
    ObjectParams params;
    Prepared sphere = prepare(make_icosphere(4), params);
    RenderedFrame frame = render(*context, {&sphere}, params, {glm::vec3(0.0f), 1.0f});
    test::InkFigures ink = test::measure_ink(frame);
    std::printf("sphere 640x512: covered %zu px, ink inside %.1f%%\n", ink.covered, 100.0 * ink.ink_fraction());
    EXPECT_GT(ink.ink_fraction(), 0.03);
    EXPECT_EQ(ink.non_white_outside, 0u);
    // The coverage mask is the depth pass: the sphere covers about pi r^2 of the frame.
    Image mask = frame.coverage_mask();
    size_t white = 0;
    for (uint8_t v : mask.pixels) white += v == 255;
    EXPECT_EQ(white, ink.covered);
}

TEST_F(RenderBasics, HiddenSphereContributesNoInk) {
    ObjectParams params;
    params.shading = false;  // every front-facing candidate drawn: the hardest case for hidden stipples
    Prepared big = prepare(make_icosphere(4, 1.0f), params);
    // Straight behind the big sphere as seen from the camera below (yaw 20, pitch 10).
    Sphere frame_on{glm::vec3(0.0f), 1.0f};
    float aspect = 640.0f / 512.0f;
    CameraMatrices camera = camera_matrices(frame_sphere(frame_on, aspect, 1.0f, 20.0f, 10.0f), aspect, frame_on);
    glm::vec3 away = glm::normalize(-camera.eye);
    Prepared small = prepare(make_icosphere(3, 0.3f), params, glm::translate(glm::mat4(1.0f), away * 1.6f));

    RenderedFrame alone = render(*context, {&big}, params, {glm::vec3(0.0f), 2.0f});
    RenderedFrame both = render(*context, {&big, &small}, params, {glm::vec3(0.0f), 2.0f});
    double differing = fraction_differing(alone.color, both.color, 0);
    std::printf("hidden sphere: %.6f%% of pixels differ\n", 100.0 * differing);
    EXPECT_EQ(differing, 0.0);

    // Control: the same small sphere beside the big one does show ink, so the comparison can fail.
    glm::vec3 side = glm::normalize(glm::cross(away, glm::vec3(0, 1, 0)));
    Prepared beside = prepare(make_icosphere(3, 0.3f), params, glm::translate(glm::mat4(1.0f), side * 1.5f));
    RenderedFrame visible = render(*context, {&big, &beside}, params, {glm::vec3(0.0f), 2.0f});
    EXPECT_GT(fraction_differing(alone.color, visible.color, 0), 0.001);
}

// An open surface seen through its hole: its faces facing away (the inside of the far wall) hide what lies
// behind them. The depth pass culled them on every object that was not two-sided or drawing object-space
// lines, so through the bunny's holes seen from below the stipples of the surfaces beyond the far wall
// showed, and turning borders on (which put the back faces in the depth pass) removed them (2026-12-07).
TEST_F(RenderBasics, WhatLiesBehindAnOpenSurfaceStaysHiddenThroughItsHole) {
    ObjectParams params;
    params.shading = false;
    Sphere frame_on{glm::vec3(0.0f), 1.0f};
    const float aspect = 640.0f / 512.0f;
    const CameraMatrices camera = camera_matrices(frame_sphere(frame_on, aspect, 1.0f, 20.0f, 10.0f), aspect, frame_on);
    const glm::vec3 toward_eye = glm::normalize(camera.eye);
    // The big sphere with the cap that faces the camera cut away (a hole a third of its radius across and more).
    Mesh open = make_icosphere(4, 1.0f);
    std::vector<uint32_t> kept;
    for (size_t t = 0; t < open.triangle_count(); ++t) {
        const glm::vec3 centroid =
            (open.positions[open.indices[3 * t]] + open.positions[open.indices[3 * t + 1]] + open.positions[open.indices[3 * t + 2]]) / 3.0f;
        if (glm::dot(glm::normalize(centroid), toward_eye) < 0.8f) kept.insert(kept.end(), open.indices.begin() + 3 * t, open.indices.begin() + 3 * t + 3);
    }
    open.indices = kept;
    Prepared shell = prepare(std::move(open), params);
    Prepared behind = prepare(make_icosphere(3, 0.3f), params, glm::translate(glm::mat4(1.0f), -toward_eye * 1.6f));
    RenderedFrame alone = render(*context, {&shell}, params, {glm::vec3(0.0f), 2.0f});
    RenderedFrame both = render(*context, {&shell, &behind}, params, {glm::vec3(0.0f), 2.0f});
    const double differing = fraction_differing(alone.color, both.color, 0);
    std::printf("sphere behind an open shell: %.6f%% of pixels differ\n", 100.0 * differing);
    EXPECT_EQ(differing, 0.0) << "stipples behind the shell's far wall show through its hole";
    write_png(test::output_path("open_shell_over_sphere.png").string(), both.color);
    EXPECT_GT(test::measure_ink(alone).ink_fraction(), 0.01) << "the shell itself is drawn";
}

TEST_F(RenderBasics, TheSplatDrawsTheSameInTheImagesWordsAsThroughACopy) {
    // Offscreen targets let the splat draw in the colour image's own memory (a linear image); other
    // targets (a window's swapchain images) get the splat's buffer copied in. Same frame both ways: over
    // paper only, and over toon surfaces, where the splat mixes its ink into the colour already there.
    Prepared sphere = prepare(make_icosphere(4), ObjectParams{});
    const VkExtent2D extent{320, 256};
    const FrameView view = unit_sphere_view(extent);
    for (bool toon : {false, true}) {
        ObjectParams params;
        params.toon = toon;
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(sphere.mesh, sphere.stipples, sphere.model, params);
        OffscreenTarget in_words(*context, extent, true), copied(*context, extent, false);
        ASSERT_NE(in_words.targets().color_words, VK_NULL_HANDLE) << "lavapipe has linear colour attachments";
        ASSERT_EQ(copied.targets().color_words, VK_NULL_HANDLE);
        const RenderedFrame a = in_words.render(renderer, view), b = copied.render(renderer, view);
        // Twice into the same words: nothing of the first frame may remain.
        const RenderedFrame again = in_words.render(renderer, view);
        size_t inked = 0;
        for (size_t i = 0; i < a.color.pixels.size(); i += 4) inked += a.color.pixels[i] < 128;
        std::printf("toon %d: %zu inked pixels; images differ in %.6f%% and %.6f%% of pixels\n", int(toon), inked,
                    100.0 * fraction_differing(a.color, b.color, 0), 100.0 * fraction_differing(a.color, again.color, 0));
        EXPECT_GT(inked, 1000u);
        EXPECT_EQ(a.color.pixels, b.color.pixels) << "toon " << toon;
        EXPECT_EQ(a.color.pixels, again.color.pixels) << "toon " << toon;
    }
}

TEST_F(RenderBasics, FramesQueuedInOneSubmissionAndTargetsTakenInTurnDrawTheSame) {
    // The bench queues frames back to back in one command buffer (OffscreenTarget::draw_queued), so the
    // splat binds a target's words only when they are new to it (by the target's serial, since a new
    // buffer may reuse a handle). Each path: queued frames, then a second target, then the first again,
    // all the reference image (a target left unbound would stay blank; a rebinding between queued frames
    // is a validation error).
    Prepared sphere = prepare(make_icosphere(4), ObjectParams{});
    const VkExtent2D extent{320, 256};
    const FrameView view = unit_sphere_view(extent);
    for (DensityPath path : {DensityPath::Splat, DensityPath::Vertex, DensityPath::Indirect, DensityPath::Cpu}) {
        ObjectParams params;
        params.density_path = path;
        params.silhouette_lines = true;
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(sphere.mesh, sphere.stipples, sphere.model, params);
        OffscreenTarget first(*context, extent);
        const RenderedFrame reference = first.render(renderer, view);
        const double ms = first.draw_queued(renderer, view, 3);
        const RenderedFrame after_queue = first.render(renderer, view);
        auto second = std::make_unique<OffscreenTarget>(*context, extent);
        const RenderedFrame on_second = second->render(renderer, view);
        second.reset();
        OffscreenTarget third(*context, extent);  // may reuse the second's handles
        const RenderedFrame on_third = third.render(renderer, view);
        const RenderedFrame first_again = first.render(renderer, view);
        size_t inked = 0;
        for (size_t i = 0; i < reference.color.pixels.size(); i += 4) inked += reference.color.pixels[i] < 128;
        std::printf("%s: %zu inked pixels, %.2f ms a queued frame, GPU passes %zu\n", density_path_name(path), inked, ms,
                    renderer.stats().gpu_ms.size());
        EXPECT_GT(inked, 1000u) << density_path_name(path);
        EXPECT_EQ(after_queue.color.pixels, reference.color.pixels) << density_path_name(path);
        EXPECT_EQ(on_second.color.pixels, reference.color.pixels) << density_path_name(path);
        EXPECT_EQ(on_third.color.pixels, reference.color.pixels) << density_path_name(path);
        EXPECT_EQ(first_again.color.pixels, reference.color.pixels) << density_path_name(path);
    }
}

}  // namespace
}  // namespace stipple
