// Copies of one model in a scene (a crowd, a molecule's atoms, a forest): static copies share their mesh,
// candidates and polygon constants on the GPU (ObjectShape), each with its own transform, parameters, lines
// and per-frame buffers, and draw exactly as the same objects drawn alone. Animated objects and other
// stipples keep shapes of their own.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/procedural_rigs.hpp"
#include "mesh/primitives.hpp"
#include "stipple/object_data.hpp"
#include "support/anim_files.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class ObjectCopies : public test::GpuTest {};

glm::mat4 at_x(float x) { return glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f)); }

TEST_F(ObjectCopies, StaticCopiesShareTheirShapeAndItsMemory) {
    const Mesh mesh = make_icosphere(4);
    ObjectParams params;
    params.generation.dmax = 0.05f;
    const StippleSet stipples = generate_stipples(mesh, params.generation);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    const uint64_t before = context->bytes_allocated();
    renderer.add_object(mesh, stipples, at_x(0.0f), params);
    const uint64_t first = context->bytes_allocated() - before;
    for (int i = 1; i < 10; ++i) renderer.add_object(mesh, stipples, at_x(3.0f * float(i)), params);
    const uint64_t ten = context->bytes_allocated() - before;
    // Generated again, the same stipples to the byte: a copy too, whatever path it came by.
    const StippleSet again = generate_stipples(mesh, params.generation);
    renderer.add_object(mesh, again, at_x(30.0f), params);
    std::printf("%zu candidates: the first object %.2f MiB, ten copies %.2f MiB (%.2f MiB a copy)\n", stipples.size(),
                double(first) / 1048576.0, double(ten) / 1048576.0, double(ten - first) / 9.0 / 1048576.0);
    for (size_t i = 1; i < renderer.object_count(); ++i) EXPECT_EQ(renderer.object(i).shape, renderer.object(0).shape) << i;
    // A copy holds its densities and its density path's lists (sized for every candidate drawn), not the mesh
    // and candidates: about 28% of the first object here, where holding the candidates again would be over 100%.
    EXPECT_LT(ten - first, 9 * first / 2) << "copies hold their own candidates";

    // Other stipples (another seed): a shape of their own.
    ObjectParams seeded = params;
    seeded.generation.seed = 2;
    const StippleSet other = generate_stipples(mesh, seeded.generation);
    renderer.add_object(mesh, other, at_x(33.0f), seeded);
    EXPECT_NE(renderer.object(renderer.object_count() - 1).shape, renderer.object(0).shape);

    // Animated copies deform their own vertices and polygons every frame: never shared.
    const ObjectData rig = load_model_data(test::write_rig(anim::rigs::bending_cylinder(), "object_copies", "cylinder"));
    const std::shared_ptr<const StippleSet> rig_stipples = make_stipples(rig, params.generation);
    StippleRenderer animated(*context, kColorFormat, context->depth_format);
    animated.add_object(*rig.mesh, *rig_stipples, at_x(0.0f), params, rig.motion);
    animated.add_object(*rig.mesh, *rig_stipples, at_x(3.0f), params, rig.motion);
    EXPECT_NE(animated.object(0).shape, animated.object(1).shape);
}

// Pixel by pixel the darker of two frames (objects apart on screen: their composite).
Image darker(const Image& a, const Image& b) {
    Image out = a;
    for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = std::min(a.pixels[i], b.pixels[i]);
    return out;
}

size_t differing_pixels(const Image& a, const Image& b) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.pixels.size(); i += 4)
        n += a.pixels[i] != b.pixels[i] || a.pixels[i + 1] != b.pixels[i + 1] || a.pixels[i + 2] != b.pixels[i + 2];
    return n;
}

// Three copies side by side, with different lines, against each drawn alone by a renderer of its own: the same
// pixels, also after a copy turns its lines on once another built the shape's edge table, and after the copy
// that made the shape is removed.
TEST_F(ObjectCopies, CopiesDrawAsTheSameObjectsAlone) {
    const Mesh mesh = make_icosphere(3);
    ObjectParams base;
    const StippleSet stipples = generate_stipples(mesh, base.generation);
    std::vector<ObjectParams> params(3, base);
    params[0].silhouette_lines = true;
    params[2].contours = true;
    params[2].creases = true;
    const VkExtent2D extent{480, 192};
    OffscreenTarget target(*context, extent);
    const FrameView view = test::framed_view(Sphere{glm::vec3(0.0f), 4.3f}, extent, 1.0f, 0.0f, 10.0f);
    const auto alone = [&](int i, const ObjectParams& p) {
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(mesh, stipples, at_x(3.0f * float(i - 1)), p);
        return target.render(renderer, view).color;
    };

    StippleRenderer crowd(*context, kColorFormat, context->depth_format);
    for (int i = 0; i < 3; ++i) crowd.add_object(mesh, stipples, at_x(3.0f * float(i - 1)), params[i]);
    ASSERT_EQ(crowd.object(1).shape, crowd.object(0).shape);
    ASSERT_EQ(crowd.object(2).shape, crowd.object(0).shape);
    const Image alone0 = alone(0, params[0]), alone2 = alone(2, params[2]);
    const Image together = target.render(crowd, view).color;
    const Image composite = darker(darker(alone0, alone(1, params[1])), alone2);
    size_t inked = 0;
    for (size_t i = 0; i < together.pixels.size(); i += 4) inked += together.pixels[i] < 128;
    std::printf("three copies: %zu inked pixels, %zu differ from the copies drawn alone\n", inked,
                differing_pixels(together, composite));
    ASSERT_GT(inked, 1000u);
    EXPECT_EQ(differing_pixels(together, composite), 0u);

    params[1].silhouette_lines = true;  // the shape's edge table is built already (copy 0's lines)
    crowd.params(1) = params[1];
    const Image alone1_lines = alone(1, params[1]);
    const Image lined = target.render(crowd, view).color;
    EXPECT_GT(differing_pixels(lined, together), 30u) << "copy 1 drew no lines";
    EXPECT_EQ(differing_pixels(lined, darker(darker(alone0, alone1_lines), alone2)), 0u);

    crowd.remove_object(0);  // the object that made the shape; the others hold it
    const Image without_first = target.render(crowd, view).color;
    EXPECT_EQ(differing_pixels(without_first, darker(alone1_lines, alone2)), 0u);
}

// The viewer adds and regenerates objects from uploads prepared on its worker thread: a copy's upload finds the
// shape too, and replacing the object that made it (new stipples) leaves its copy drawing as before.
TEST_F(ObjectCopies, UploadsShareAndAReplacedObjectLeavesItsCopies) {
    const Mesh mesh = make_icosphere(3);
    ObjectParams params;
    const StippleSet stipples = generate_stipples(mesh, params.generation);
    const VkExtent2D extent{320, 128};
    OffscreenTarget target(*context, extent);
    const FrameView view = test::framed_view(Sphere{glm::vec3(0.0f), 2.9f}, extent, 1.0f, 0.0f, 10.0f);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(prepare_object_upload(*context, mesh, stipples, params.generation.seed), at_x(-1.5f), params);
    renderer.add_object(prepare_object_upload(*context, mesh, stipples, params.generation.seed), at_x(1.5f), params);
    ASSERT_EQ(renderer.object(1).shape, renderer.object(0).shape);
    const Image before = target.render(renderer, view).color;

    // The same stipples again: the object takes the shape back; the frame is the same.
    renderer.replace_object(0, prepare_object_upload(*context, mesh, stipples, params.generation.seed));
    EXPECT_EQ(renderer.object(0).shape, renderer.object(1).shape);
    EXPECT_EQ(differing_pixels(target.render(renderer, view).color, before), 0u);

    // Other stipples: a shape of its own; the copy, now alone with the first shape, draws its half as before.
    ObjectParams seeded = params;
    seeded.generation.seed = 2;
    renderer.replace_object(0, prepare_object_upload(*context, mesh, generate_stipples(mesh, seeded.generation), seeded.generation.seed));
    EXPECT_NE(renderer.object(0).shape, renderer.object(1).shape);
    const Image after = target.render(renderer, view).color;
    size_t left = 0, right = 0;  // differing pixels in each half (the first object on the left)
    for (int y = 0; y < int(extent.height); ++y)
        for (int x = 0; x < int(extent.width); ++x) {
            const size_t i = 4 * (size_t(y) * extent.width + size_t(x));
            (x < int(extent.width) / 2 ? left : right) += after.pixels[i] != before.pixels[i];
        }
    std::printf("replaced with other stipples: %zu pixels differ on its side, %zu on its copy's\n", left, right);
    EXPECT_GT(left, 50u);
    EXPECT_EQ(right, 0u);
}

}  // namespace
}  // namespace stipple
