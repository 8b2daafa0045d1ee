// The per-object up axis (issue 13): a model file whose up is z (or x, or a negative axis) is turned
// about its bounding-sphere centre so that axis points up, before the scene's transform.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "io/png_io.hpp"
#include "render/object_gpu.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

// Width and height of the box holding the image's non-paper pixels.
glm::ivec2 ink_extent(const Image& image) {
    glm::ivec2 lo(image.width, image.height), hi(-1, -1);
    for (int y = 0; y < int(image.height); ++y)
        for (int x = 0; x < int(image.width); ++x) {
            const uint8_t* p = &image.pixels[4 * (size_t(y) * image.width + x)];
            if (p[0] > 200 && p[1] > 200 && p[2] > 200) continue;
            lo = glm::min(lo, glm::ivec2(x, y));
            hi = glm::max(hi, glm::ivec2(x, y));
        }
    return hi.x < 0 ? glm::ivec2(0) : hi - lo + 1;
}

TEST(UpAxes, EachRotationTakesItsAxisToYAboutTheCentre) {
    const glm::vec3 center(1.0f, -2.0f, 3.0f);
    const struct {
        UpAxis up;
        glm::vec3 axis;
    } cases[] = {{UpAxis::X, {1, 0, 0}},  {UpAxis::Y, {0, 1, 0}},  {UpAxis::Z, {0, 0, 1}},
                 {UpAxis::NegX, {-1, 0, 0}}, {UpAxis::NegY, {0, -1, 0}}, {UpAxis::NegZ, {0, 0, -1}}};
    for (const auto& c : cases) {
        glm::mat4 m = up_axis_rotation(c.up, center);
        glm::vec3 up = glm::vec3(m * glm::vec4(c.axis, 0.0f));
        EXPECT_NEAR(glm::distance(up, glm::vec3(0, 1, 0)), 0.0f, 1e-6f) << int(c.up);
        EXPECT_NEAR(glm::distance(glm::vec3(m * glm::vec4(center, 1.0f)), center), 0.0f, 1e-5f) << int(c.up);
        EXPECT_NEAR(glm::determinant(glm::mat3(m)), 1.0f, 1e-6f) << int(c.up);  // a rotation, not a mirror
    }
}

TEST(UpAxes, UpZStandsABoxAlongZUpright) {
    // A box four times taller along z than across, seen from the default view (the camera on +z).
    std::filesystem::path dir = test::temp_dir("up_axis");
    const std::string box = test::write_file(dir / "tall_box.obj", test::obj_text(test::make_box({1.0f, 1.0f, 4.0f})));
    glm::ivec2 extent_of[2];
    for (int i = 0; i < 2; ++i) {
        const std::string up = i == 0 ? "z" : "y";
        const std::string png = (dir / ("box_up_" + up + ".png")).string();
        test::CommandResult r = test::run_stipple(
            {"render", box, "-o", png, "--width", "256", "--height", "256", "--up", up, "--silhouette", "lines"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        extent_of[i] = ink_extent(read_png(png));
        std::filesystem::copy_file(png, test::output_path("up_axis_box_" + up + ".png"),
                                   std::filesystem::copy_options::overwrite_existing);
        std::printf("--up %s: the box's image is %d x %d px\n", up.c_str(), extent_of[i].x, extent_of[i].y);
    }
    EXPECT_GT(extent_of[0].y, 2 * extent_of[0].x);  // upright: four times taller than wide, in perspective
    EXPECT_LT(extent_of[1].y, extent_of[1].x * 5 / 4);  // lying along the view: about square
    // A scene file says the same per object.
    test::write_file(dir / "scene.json", R"({"objects": [{"model": "tall_box.obj", "params": {"up": "z"}}]})");
    const std::string png = (dir / "scene.png").string();
    test::CommandResult r = test::run_stipple({"render", (dir / "scene.json").string(), "-o", png, "--width", "256",
                                               "--height", "256"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    glm::ivec2 scene = ink_extent(read_png(png));
    EXPECT_GT(scene.y, 2 * scene.x);
    // A bad axis is one line naming the option.
    r = test::run_stipple({"render", box, "-o", png, "--up", "w"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("--up 'w' is not one of x, y, z, -x, -y, -z"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stipple
