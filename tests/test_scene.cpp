// Scene files: a saved scene loads back to the same image; objects in one frame keep their own
// parameters and their own distance enhancement (paper §2.3, Fig. 3); and every malformed file gets
// one line naming the file, the field and the problem (API and command line alike).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/procedural_rigs.hpp"
#include "app/live_scene.hpp"
#include "app/timeline.hpp"
#include "core/error.hpp"
#include "io/png_io.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/primitives.hpp"
#include "scene/frame_sequence.hpp"
#include "scene/scene_content.hpp"
#include "scene/scene_json.hpp"
#include "support/anim_files.hpp"
#include "support/gpu_test.hpp"
#include "support/image_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class SceneObjects : public test::GpuTest {};

void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// `mesh` as an OBJ file, each position through `place` (9 digits: test::obj_text's fixed 6 decimals lose a model
// 1e-8 units across): scenes refer to models by path.
template <class Place>
std::filesystem::path write_mesh_obj(const std::filesystem::path& dir, const std::string& name, const Mesh& mesh, Place place) {
    std::ostringstream obj;
    obj.precision(9);
    for (const glm::vec3& position : mesh.positions) {
        const auto p = place(position);  // glm::vec3, or glm::dvec3 for a model far from its origin
        obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
    for (size_t t = 0; t < mesh.triangle_count(); ++t)
        obj << "f " << mesh.indices[3 * t] + 1 << ' ' << mesh.indices[3 * t + 1] + 1 << ' ' << mesh.indices[3 * t + 2] + 1
            << '\n';
    write_text(dir / name, obj.str());
    return dir / name;
}

// `mesh` scaled along its axes as an OBJ file.
std::filesystem::path write_mesh_obj(const std::filesystem::path& dir, const std::string& name, const Mesh& mesh,
                                     glm::vec3 scale = glm::vec3(1.0f)) {
    return write_mesh_obj(dir, name, mesh, [&](const glm::vec3& p) { return p * scale; });
}

// A unit sphere as an OBJ file.
std::filesystem::path write_sphere_obj(const std::filesystem::path& dir, int subdivisions = 4,
                                       const std::string& name = "sphere.obj") {
    return write_mesh_obj(dir, name, make_icosphere(subdivisions));
}

RenderedFrame render_scene(const gpu::Context& context, const Scene& scene, VkExtent2D extent,
                           const RendererOptions& options = {}) {
    SceneContent content = load_scene_content(scene);
    StippleRenderer renderer(context, kColorFormat, context.depth_format, options);
    add_scene_objects(renderer, scene, content.objects);
    Sphere bounds = scene_bounds(scene, content.objects);
    float aspect = float(extent.width) / float(extent.height);
    OrbitCamera camera = frame_cameras(scene, bounds, aspect, 1, std::nullopt).at(0);
    OffscreenTarget target(context, extent);
    return target.render(renderer, scene_frame_view(scene, camera, bounds, extent));
}

// Mean darkness over the covered pixels left and right of column `split`.
std::pair<double, double> tone_left_right(const RenderedFrame& frame, int split) {
    double sum[2] = {0, 0};
    size_t count[2] = {0, 0};
    for (int y = 0; y < frame.color.height; ++y)
        for (int x = 0; x < frame.color.width; ++x) {
            size_t i = size_t(y) * frame.color.width + x;
            if (frame.depth[i] >= 1.0f) continue;
            int side = x < split ? 0 : 1;
            sum[side] += 1.0 - frame.color.pixels[4 * i] / 255.0;
            ++count[side];
        }
    EXPECT_GT(count[0], 1000u) << "left object not in the frame";
    EXPECT_GT(count[1], 300u) << "right object not in the frame";
    return {count[0] ? sum[0] / count[0] : 0.0, count[1] ? sum[1] / count[1] : 0.0};
}

Scene two_spheres(const std::filesystem::path& dir, float dmax_left, float dmax_right) {
    Scene scene;
    scene.base_dir = dir;
    SceneObject left, right;
    left.model = right.model = "sphere.obj";
    left.transform.translate = {-1.25f, 0.0f, 0.0f};
    right.transform.translate = {1.25f, 0.0f, 0.0f};
    left.params.generation.dmax = dmax_left;
    right.params.generation.dmax = dmax_right;
    scene.objects = {left, right};
    return scene;
}

TEST_F(SceneObjects, SavedSceneLoadsBackToTheSameImage) {
    auto dir = test::temp_dir("scene-roundtrip");
    write_sphere_obj(dir);
    Scene scene = two_spheres(dir, 0.08f, 0.2f);
    scene.objects[0].transform.rotate_deg = {10.0f, 20.0f, 30.0f};
    scene.objects[0].transform.scale = 0.9f;
    ObjectParams& p = scene.objects[0].params;
    p.generation.seed = 7;
    p.generation.relax_iterations = 4;
    p.generation.max_stipples = 200000;
    p.shading_exponent = 2.5f;
    p.pr = 1.5f;
    p.min_area = 3.0f;
    p.de = 1.25f;
    p.point_size = 2.5f;
    p.density_path = DensityPath::Cpu;
    p.silhouette_width = 3.0f;
    p.silhouette_thinning = false;
    p.toon_sharpness = 8.0f;
    scene.objects[1].transform.matrix =
        glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.3f, 0.2f, -0.4f)), glm::vec3(0.5f));
    scene.objects[1].params.intrinsic = false;
    scene.objects[1].params.density_path = DensityPath::Indirect;
    scene.objects[1].params.ink = glm::vec3(0.2f, 0.4f, 0.9f);
    scene.camera.yaw_deg = 30.0f;
    scene.camera.pitch_deg = 15.0f;
    scene.camera.distance = 1.1f;
    scene.camera_path = {scene.camera, SceneCamera{}};
    scene.camera_path[1].world_distance = 9.0f;
    scene.camera_path[1].target = glm::vec3(0.1f, 0.2f, 0.3f);
    scene.camera_path[1].orthographic = true;
    scene.light = {0.3f, 0.8f, 0.5f};
    scene.paper = {1.0f, 0.95f, 0.9f};
    scene.ink = {0.1f, 0.05f, 0.0f};
    scene.paused = true;

    // Saved one folder down: the model path must be rewritten relative to the new file.
    std::string file = (dir / "saved" / "scene.json").string();
    save_scene(file, scene);
    std::string text = read_text(file);
    EXPECT_NE(text.find("\"../sphere.obj\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"dmax\": 0.08"), std::string::npos) << "floats are written in their short form\n" << text;
    Scene loaded = load_scene(file);
    ASSERT_EQ(loaded.objects.size(), 2u);
    EXPECT_TRUE(std::filesystem::equivalent(loaded.model_path(0), scene.model_path(0)));
    EXPECT_EQ(scene_to_json(loaded, dir), scene_to_json(scene, dir)) << "every field survives the round trip";
    EXPECT_FALSE(loaded.objects[0].params.ink) << "an object without an ink of its own takes the scene's";
    EXPECT_TRUE(loaded.paused) << text;
    EXPECT_FALSE(loaded.camera_path.at(0).orthographic);
    EXPECT_TRUE(loaded.camera_path.at(1).orthographic) << text;
    ASSERT_TRUE(loaded.objects[1].params.ink);
    EXPECT_EQ(*loaded.objects[1].params.ink, glm::vec3(0.2f, 0.4f, 0.9f));

    RenderedFrame original = render_scene(*context, scene, {400, 300});
    RenderedFrame again = render_scene(*context, loaded, {400, 300});
    EXPECT_EQ(fraction_differing(original.color, again.color, 0), 0.0) << "the loaded scene draws another image";
    EXPECT_GT(test::measure_ink(original).inked_inside, 500u) << "the scene should draw stipples";
}

// A scene file is JSON, which is UTF-8: a model whose file name is not (a Latin-1 name) cannot be saved in
// one. Saving says so in one line naming the object, where the JSON library threw an exception that ended
// the viewer (Ctrl+S).
TEST(Scene, AModelNameThatIsNotUtf8IsAOneLineError) {
    Scene scene;
    scene.objects.push_back({"caf\xe9.obj", {}, {}});
    try {
        scene_to_json(scene, test::temp_dir("scene_latin1"));
        ADD_FAILURE() << "a scene naming a file that is not UTF-8 was written";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("objects[0].model: the path is not UTF-8"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    scene.objects[0].model = "caf\xc3\xa9.obj";  // the same name in UTF-8
    EXPECT_NE(scene_to_json(scene, test::temp_dir("scene_latin1")).find("caf\xc3\xa9.obj"), std::string::npos);
}

// A scene file of many MiB is refused by its size, before it is read (a sparse file: no disk, no memory).
TEST(Scene, AHugeSceneFileIsRefusedByItsSize) {
    const auto file = test::temp_dir("scene-huge") / "huge.json";
    { std::ofstream(file) << "{}"; }
    std::filesystem::resize_file(file, uint64_t(1) << 30);
    std::string message;
    try {
        load_scene(file.string());
    } catch (const Error& e) {
        message = e.what();
    }
    EXPECT_NE(message.find(file.string() + ": is 1.0 GiB: a scene file is at most 64.0 MiB"), std::string::npos) << message;
    std::filesystem::remove(file);
}

TEST(Scene, EnumsAndFlagsSurviveTheTextRoundTrip) {
    auto dir = test::temp_dir("scene-text");
    Scene scene = parse_scene(R"({"objects": [{"model": "a.obj", "params": {"silhouette": "toon", "shading": false,
        "extrinsic": false, "silhouette_thinning": false, "density_path": "indirect"}}]})",
                              "inline.json", dir);
    Scene back = parse_scene(scene_to_json(scene, dir), "again.json", dir);
    const ObjectParams& p = back.objects.at(0).params;
    EXPECT_TRUE(p.toon) << "the old \"silhouette\": \"toon\" spelling sets the toon switch";
    EXPECT_FALSE(p.silhouette_lines);
    EXPECT_FALSE(p.shading);
    EXPECT_FALSE(p.extrinsic);
    EXPECT_TRUE(p.intrinsic);
    EXPECT_FALSE(p.silhouette_thinning);
    EXPECT_EQ(p.density_path, DensityPath::Indirect);
}

// "scale" takes one number or one an axis (a terrain's heights exaggerated: [1, 3, 1]): translate * rotate * scale,
// saved as it was written ("expected a number, got array" until 2026-12-05).
TEST(Scene, AScaleAnAxisIsTheMatrixOfTheTransform) {
    auto dir = test::temp_dir("scene-axis-scale");
    const Scene scene = parse_scene(R"({"objects": [{"model": "a.obj", "transform": {"translate": [1, 2, 3],
        "rotate_deg": [0, 90, 0], "scale": [2, 3, 4]}}]})", "inline.json", dir);
    const glm::mat4 m = scene.objects.at(0).transform.to_matrix();
    EXPECT_NEAR(glm::length(glm::vec3(m[0])), 2.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(m[1])), 3.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(m[2])), 4.0f, 1e-6f);
    EXPECT_NEAR(m[0][2], -2.0f, 1e-6f) << "x turned a quarter about y, then scaled by 2";
    EXPECT_EQ(glm::vec3(m[3]), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FALSE(scene.objects.at(0).transform.matrix) << "translate, rotate and scale stay editable";
    const std::string saved = scene_to_json(scene, dir);
    EXPECT_NE(saved.find("\"scale\": ["), std::string::npos) << saved;
    const Scene back = parse_scene(saved, "again.json", dir);
    EXPECT_EQ(back.objects.at(0).transform.to_matrix(), m);
    // A negative scale mirrors its axis, and is saved as written.
    const Scene mirror = parse_scene(R"({"objects": [{"model": "a.obj", "transform": {"scale": [1, -2, 1]}}]})", "m.json", dir);
    EXPECT_TRUE(mirror.objects.at(0).transform.mirrors());
    EXPECT_TRUE(parse_scene(R"({"objects": [{"model": "a.obj", "transform": {"matrix": [-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}]})",
                            "mm.json", dir).objects.at(0).transform.mirrors());
    EXPECT_FALSE(scene.objects.at(0).transform.mirrors());
    EXPECT_EQ(parse_scene(scene_to_json(mirror, dir), "m2.json", dir).objects.at(0).transform.to_matrix(),
              mirror.objects.at(0).transform.to_matrix());
    for (const char* bad : {R"([1, 0, 1])", R"([1, 2])", R"([1, -1e-9, 1])", R"([-2e6, 1, 1])"}) {
        try {
            parse_scene(std::string(R"({"objects": [{"model": "a.obj", "transform": {"scale": )") + bad + "}}]}", "bad.json", dir);
            ADD_FAILURE() << bad << " was taken";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("objects[0].transform.scale"), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}

// Models side by side on the command line share its --animation: the animated ones play it and a static one
// ignores it (`view fox.glb spot.obj --animation Walk` was refused for spot until 2026-12-05). A static model
// alone, or in a scene file that names an animation for it, is still refused.
TEST(SceneContent, ModelsSideBySideShareTheCommandLinesAnimation) {
    const auto dir = test::temp_dir("scene-shared-animation");
    const std::string sphere = write_sphere_obj(dir, 2).string();
    const std::string rig = test::write_rig(anim::rigs::bending_cylinder(), "scene-shared-animation-rig", "cylinder");
    Scene pair;
    pair.objects.push_back({rig, {}, {}});
    pair.objects.push_back({sphere, {}, {}});
    for (SceneObject& o : pair.objects) o.animation.name = "Bend";
    const SceneContent content = load_scene_models(pair);
    drop_animations_of_static_models(pair, content);
    EXPECT_EQ(pair.objects[0].animation.name, "Bend");
    EXPECT_TRUE(pair.objects[1].animation.is_default());
    // The refusal load_scene_models gives, or "" where it took the scene.
    auto refusal = [](const Scene& scene) {
        try {
            load_scene_models(scene);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Scene alone;
    alone.objects.push_back({sphere, {}, {}});
    alone.objects[0].animation.name = "Bend";
    EXPECT_NE(refusal(alone).find("has no animation to play"), std::string::npos) << "a static model alone took --animation";
    Scene file = pair;
    file.source = (dir / "scene.json").string();
    file.objects[1].animation.name = "Bend";
    EXPECT_NE(refusal(file).find("objects[1].animation.name"), std::string::npos)
        << "a scene file's animation for a static model was taken";
}

TEST_F(SceneObjects, ObjectsInOneFrameKeepTheirOwnDensity) {
    auto dir = test::temp_dir("scene-two-objects");
    write_sphere_obj(dir);
    VkExtent2D extent{640, 320};
    // Light and dark: each sphere draws with its own D_max; swapping the values swaps the tones.
    RenderedFrame first = render_scene(*context, two_spheres(dir, 0.03f, 0.25f), extent);
    write_png(test::output_path("scene_two_objects.png").string(), first.color);
    auto [light_left, dark_right] = tone_left_right(first, 320);
    auto [dark_left, light_right] = tone_left_right(render_scene(*context, two_spheres(dir, 0.25f, 0.03f), extent), 320);
    std::printf("tone left/right: dmax 0.03|0.25 -> %.3f|%.3f, 0.25|0.03 -> %.3f|%.3f\n", light_left, dark_right,
                dark_left, light_right);
    EXPECT_LT(light_left, 0.6 * dark_right);
    EXPECT_LT(light_right, 0.6 * dark_left);
    EXPECT_NEAR(light_left, light_right, 0.25 * light_left) << "the same parameters should give the same tone";
}

// Every pair of density paths in one frame draws each object as it draws alone: the tone of each of two
// spheres is the same whichever paths they take (all paths draw the same stipples). Found on lavapipe:
// an indirect-path object before a cpu-path one made the cpu one draw only as many of its ranges as the
// first had drawn polygons (hence a 20-polygon sphere first).
TEST_F(SceneObjects, EveryPairOfDensityPathsDrawsTheSameStipples) {
    auto dir = test::temp_dir("scene-path-pairs");
    write_sphere_obj(dir);
    write_sphere_obj(dir, 0, "icosahedron.obj");
    const VkExtent2D extent{480, 240};
    Scene reference = two_spheres(dir, 0.25f, 0.25f);
    reference.objects[0].model = "icosahedron.obj";
    const RenderedFrame expected = render_scene(*context, reference, extent);
    const auto [left_ink, right_ink] = tone_left_right(expected, 240);
    for (DensityPath left : {DensityPath::Vertex, DensityPath::Indirect, DensityPath::Cpu, DensityPath::Splat, DensityPath::CpuSplat})
        for (DensityPath right : {DensityPath::Vertex, DensityPath::Indirect, DensityPath::Cpu, DensityPath::Splat, DensityPath::CpuSplat}) {
            Scene scene = reference;
            scene.objects[0].params.density_path = left;
            scene.objects[1].params.density_path = right;
            const auto [l, r] = tone_left_right(render_scene(*context, scene, extent), 240);
            EXPECT_NEAR(l, left_ink, 0.02 * left_ink) << density_path_name(left) << " then " << density_path_name(right);
            EXPECT_NEAR(r, right_ink, 0.02 * right_ink) << density_path_name(left) << " then " << density_path_name(right);
        }
}

// Where a pixel of the columns [x0, x1) holds ink: its colour away from the paper (white), and whether it lies
// on the way from the paper to `ink` (mix(paper, ink, a) for some a, within rounding): what every stipple,
// fractional one, line and toon shade of an object drawn in that ink leaves.
struct InkHue {
    size_t inked = 0, on_the_way = 0;
};
InkHue ink_hue(const RenderedFrame& frame, int x0, int x1, glm::vec3 ink) {
    InkHue hue;
    for (int y = 0; y < frame.color.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const uint8_t* p = &frame.color.pixels[4 * (size_t(y) * frame.color.width + x)];
            const glm::vec3 c(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
            if (glm::all(glm::greaterThan(c, glm::vec3(0.98f)))) continue;  // paper
            ++hue.inked;
            hue.on_the_way += test::on_the_way(c, glm::vec3(1.0f), ink);
        }
    return hue;
}

// Each object draws in its own ink (ObjectParams::ink), not the scene's, on every density path, with the
// Raskar-Cohen lines (drawn against the depth image, or against the compute depth pass's words), the
// object-space contours and the toon shade: the left sphere red, the right one blue, the scene's ink green,
// each pixel of each side a mix of the paper and that side's ink alone.
TEST_F(SceneObjects, EachObjectDrawsInItsOwnInk) {
    auto dir = test::temp_dir("scene-object-inks");
    write_sphere_obj(dir);
    const VkExtent2D extent{480, 240};
    Scene scene = two_spheres(dir, 0.25f, 0.25f);
    const glm::vec3 red(0.9f, 0.1f, 0.1f), blue(0.1f, 0.2f, 0.8f), green(0.1f, 0.6f, 0.1f);
    scene.ink = green;
    scene.objects[0].params.ink = red;
    scene.objects[1].params.ink = blue;
    for (SceneObject& o : scene.objects) o.params.silhouette_lines = o.params.contours = true;
    for (const DepthRaster raster : {DepthRaster::Fixed, DepthRaster::Compute})
        for (DensityPath path : kAllDensityPaths) {
            // A toon object makes the frame's depth pass the fixed one (depth_raster.hpp): toon with it alone.
            if (raster == DepthRaster::Compute && path != DensityPath::Splat && path != DensityPath::Vertex) continue;
            for (SceneObject& o : scene.objects) {
                o.params.density_path = path;
                o.params.toon = raster == DepthRaster::Fixed;
            }
            RendererOptions options;
            options.depth_raster = raster;
            const RenderedFrame frame = render_scene(*context, scene, extent, options);
            const std::string what = std::string(density_path_name(path)) + (raster == DepthRaster::Fixed ? ", fixed depth" : ", compute depth");
            const InkHue left = ink_hue(frame, 0, 240, red), right = ink_hue(frame, 240, 480, blue);
            std::printf("%s: left %zu inked px, %.2f%% of them red ink on paper; right %zu, %.2f%% blue\n", what.c_str(),
                        left.inked, 100.0 * double(left.on_the_way) / double(left.inked), right.inked,
                        100.0 * double(right.on_the_way) / double(right.inked));
            EXPECT_GT(left.inked, 2000u) << what;
            EXPECT_GT(right.inked, 2000u) << what;
            // Any pixel in another colour is drawn in the wrong ink (or mixed with it): none is.
            EXPECT_EQ(left.on_the_way, left.inked) << what;
            EXPECT_EQ(right.on_the_way, right.inked) << what;
            // Nor in the scene's.
            EXPECT_LT(ink_hue(frame, 0, 480, green).on_the_way, (left.inked + right.inked) / 20) << what;
        }
}

TEST_F(SceneObjects, ObjectsAtDifferentScalesKeepTheirTone) {
    // Paper Fig. 3: a large and a small object in one image. The extrinsic enhancement works per
    // object, from each one's own scale on screen, so both keep the tone their parameters ask for.
    // Turning it off for the small object alone crams all its candidates into few pixels: it darkens,
    // and the large object does not change.
    auto dir = test::temp_dir("scene-scales");
    write_sphere_obj(dir);
    auto tones = [&](bool small_extrinsic) {
        Scene scene = two_spheres(dir, 0.04f, 0.04f);
        scene.objects[0].transform.translate = {-0.9f, 0.0f, 0.0f};
        scene.objects[1].transform.translate = {1.6f, 0.0f, 0.0f};  // a wide gap: column 475 parts them
        scene.objects[1].transform.scale = 0.3f;
        scene.objects[1].params.extrinsic = small_extrinsic;
        auto [big, small] = tone_left_right(render_scene(*context, scene, {800, 400}), 475);
        std::printf("small object's extrinsic %s: tone big %.3f, small %.3f\n", small_extrinsic ? "on" : "off", big,
                    small);
        return std::make_pair(big, small);
    };
    auto [big_on, small_on] = tones(true);
    auto [big_off, small_off] = tones(false);
    EXPECT_GT(small_on / big_on, 0.6) << "same parameters, different scales: the tone should hold";
    EXPECT_LT(small_on / big_on, 1.6) << "same parameters, different scales: the tone should hold";
    EXPECT_GT(small_off, 2.0 * small_on) << "without its enhancement the small object should darken";
    EXPECT_NEAR(big_off, big_on, 0.02) << "the other object's enhancement is its own";
}

// A scene matrix that scales the axes unequally: each polygon's area follows its own orientation
// (|det M| |M^-T n|), not the mean scale. A plate squashed 3x across its plane is the plate itself, and
// one stretched 3x along it draws what the same plate stored stretched draws, but for the overlap of its
// stretched (anisotropic) pattern. Taken at the mean scale they drew 1.5 and 0.69 times the stipples.
TEST_F(SceneObjects, AnUnequalScaleOfTheAxesKeepsThePolygonsTone) {
    auto dir = test::temp_dir("scene-unequal-scale");
    write_mesh_obj(dir, "plate.obj", make_grid(20));
    write_mesh_obj(dir, "wide.obj", make_grid(20), glm::vec3(3.0f, 1.0f, 1.0f));
    auto ink = [&](const std::string& model, glm::vec3 scale) {
        Scene scene;
        scene.base_dir = dir;
        SceneObject object;
        object.model = model;
        object.transform.matrix = glm::scale(glm::mat4(1.0f), scale);
        object.params.shading = false;
        object.params.intrinsic = false;
        scene.objects = {object};
        scene.camera.world_distance = 12.0f;
        scene.camera.target = glm::vec3(0.0f);
        const RenderedFrame frame = render_scene(*context, scene, {640, 512});
        double sum = 0.0;
        size_t covered = 0;
        for (size_t i = 0; i < frame.depth.size(); ++i) {
            if (frame.depth[i] >= 1.0f) continue;
            sum += 1.0 - frame.color.pixels[4 * i] / 255.0;
            ++covered;
        }
        EXPECT_GT(covered, 10000u) << model;
        return sum / double(covered);
    };
    const double plate = ink("plate.obj", glm::vec3(1.0f)), squashed = ink("plate.obj", glm::vec3(1.0f, 1.0f, 3.0f));
    const double stored = ink("wide.obj", glm::vec3(1.0f)), stretched = ink("plate.obj", glm::vec3(3.0f, 1.0f, 1.0f));
    std::printf("mean ink: plate %.4f, scaled 3x across its plane %.4f; stored 3x wider %.4f, scaled 3x wider %.4f\n", plate,
                squashed, stored, stretched);
    EXPECT_NEAR(squashed, plate, 0.01 * plate);
    EXPECT_NEAR(stretched, stored, 0.08 * stored);  // 6% lighter measured: its dots overlap more across the stretch
}

// A flat object under a matrix that scales its thin axis (a terrain's heights exaggerated) is framed by the
// sphere around its box, as if stored scaled: its bounding sphere stretched by the whole stretch framed a
// plate scaled 3 times along its width 0.745 times as wide as the same plate stored wide, and a terrain whose
// heights were multiplied by 10 at a tenth of the frame (a sci-vis walkthrough, 2026-12-05).
TEST_F(SceneObjects, AnUnequalScaleFramesTheObjectAsStoredScaled) {
    auto dir = test::temp_dir("scene-unequal-framing");
    write_mesh_obj(dir, "plate.obj", make_grid(20));
    write_mesh_obj(dir, "wide.obj", make_grid(20), glm::vec3(3.0f, 1.0f, 1.0f));
    auto covered = [&](const std::string& model, glm::vec3 scale) {
        Scene scene;
        scene.base_dir = dir;
        SceneObject object;
        object.model = model;
        object.transform.matrix = glm::scale(glm::mat4(1.0f), scale);
        object.params.borders = true;
        scene.objects = {object};
        scene.camera.pitch_deg = 30.0f;
        const RenderedFrame frame = render_scene(*context, scene, {640, 512});
        size_t n = 0;
        for (float d : frame.depth) n += d < 1.0f;
        return n;
    };
    const size_t stored = covered("wide.obj", glm::vec3(1.0f)), stretched = covered("plate.obj", glm::vec3(3.0f, 1.0f, 1.0f));
    std::printf("covered pixels: stored 3x wider %zu, scaled 3x wider by the matrix %zu\n", stored, stretched);
    EXPECT_GT(stored, 20000u);
    EXPECT_NEAR(double(stretched), double(stored), 0.01 * double(stored));

    // The same for a terrain stored Z-up (up z: the drawing turns it a quarter about x, so the matrix's y scales the
    // file's heights), and its lines: the outline's thinning takes the same world radius (it was the sphere times
    // 3). Turned, the box is wide in x and z and thin in y; unturned it would be thin in the matrix's z.
    const Mesh grid = make_grid(40);
    auto write_terrain = [&](const std::string& name, float height) {
        write_mesh_obj(dir, name, grid, [&](const glm::vec3& p) {
            return glm::vec3(p.x, p.y, height * 0.1f * std::sin(6.0f * p.x) * std::cos(5.0f * p.y));
        });
    };
    write_terrain("terrain.obj", 1.0f);
    write_terrain("tall.obj", 3.0f);
    auto drawn = [&](const std::string& model, UpAxis up, glm::vec3 scale) {
        Scene scene;
        scene.base_dir = dir;
        SceneObject object;
        object.model = model;
        object.transform.matrix = glm::scale(glm::mat4(1.0f), scale);
        object.params.up = up;
        object.params.generation.dmax = 0.0f;  // the outline alone
        object.params.borders = true;
        scene.objects = {object};
        scene.camera.pitch_deg = 30.0f;
        const RenderedFrame frame = render_scene(*context, scene, {640, 512});
        std::pair<size_t, size_t> covered_and_dark{0, 0};
        for (size_t i = 0; i < frame.depth.size(); ++i) {
            covered_and_dark.first += frame.depth[i] < 1.0f;
            covered_and_dark.second += frame.color.pixels[4 * i] < 128;
        }
        return covered_and_dark;
    };
    const auto tall = drawn("tall.obj", UpAxis::Z, glm::vec3(1.0f)), raised = drawn("terrain.obj", UpAxis::Z, glm::vec3(1.0f, 3.0f, 1.0f));
    std::printf("Z-up terrain: heights stored 3x %zu covered, %zu dark; scaled by the matrix %zu, %zu\n", tall.first, tall.second,
                raised.first, raised.second);
    EXPECT_GT(tall.second, 500u);
    // Within the box's slack: the sphere around the box's corners is a little wider than the stored terrain's own
    // (4.5% fewer pixels measured); the stretched sphere framed it at about a seventh of them.
    EXPECT_NEAR(double(raised.first), double(tall.first), 0.07 * double(tall.first));
    EXPECT_NEAR(double(raised.second), double(tall.second), 0.05 * double(tall.second));
}

// Lines are as wide on a model of any size: the thinning's distance to the object was floored at 1e-6 units, more
// than the whole camera distance of a model 1e-8 units across, whose outline then came out half as heavy.
TEST_F(SceneObjects, LinesAreAsWideOnAModelOfAnySize) {
    auto dir = test::temp_dir("scene-line-units");
    const Mesh sphere = make_icosphere(3);
    auto dark = [&](float scale) {
        const std::string name = "sphere_" + std::to_string(scale) + ".obj";
        write_mesh_obj(dir, name, sphere, glm::vec3(scale));
        Scene scene;
        scene.base_dir = dir;
        SceneObject object;
        object.model = name;
        object.params.generation.dmax = 0.0f;  // the outline alone
        object.params.contours = true;
        scene.objects = {object};
        const RenderedFrame frame = render_scene(*context, scene, {320, 256});
        size_t n = 0;
        for (size_t i = 0; i < frame.color.pixels.size(); i += 4) n += frame.color.pixels[i] < 128;
        return n;
    };
    const size_t unit = dark(1.0f), tiny = dark(1e-8f), huge = dark(1e8f);
    std::printf("outline dark pixels: unit %zu, 1e-8 %zu, 1e8 %zu\n", unit, tiny, huge);
    EXPECT_GT(unit, 500u);
    EXPECT_NEAR(double(tiny), double(unit), 0.02 * double(unit));
    EXPECT_NEAR(double(huge), double(unit), 0.02 * double(unit));
}

// A model far from its file's origin (a scan in survey coordinates) keeps its shape: it is read in double and
// stored about its own centre, and the drawing puts it back where the file has it. A unit sphere 3e4 units out
// was stored in single precision there, its stipples on a lattice of float steps: 30.9% of ink against 36.0%.
// Two copies side by side in one scene keep their places.
TEST_F(SceneObjects, AModelFarFromItsOriginKeepsItsShape) {
    auto dir = test::temp_dir("scene-far-origin");
    const Mesh sphere = make_icosphere(4);
    const glm::vec3 far(3e4f, -2e4f, 1e4f);
    write_mesh_obj(dir, "near.obj", sphere);
    write_mesh_obj(dir, "far.obj", sphere, [&](const glm::vec3& p) { return glm::dvec3(p) + glm::dvec3(far); });
    Mesh stray = sphere;  // and a vertex no face uses, left at the file's origin (it hid how far the model lies)
    stray.positions.push_back(-far);
    stray.normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
    write_mesh_obj(dir, "far_stray.obj", stray, [&](const glm::vec3& p) { return glm::dvec3(p) + glm::dvec3(far); });
    for (const char* name : {"far.obj", "far_stray.obj"}) {
        const Mesh loaded = load_mesh((dir / name).string());
        EXPECT_NEAR(loaded.origin.x, 3e4, 1e-3) << name;
        EXPECT_NEAR(total_area(loaded), total_area(sphere), 1e-4 * total_area(sphere)) << name << ": the shape is kept";
    }
    auto draw = [&](const std::string& model, std::vector<glm::vec3> places) {
        Scene scene;
        scene.base_dir = dir;
        for (const glm::vec3& at : places) {
            SceneObject object;
            object.model = model;
            object.transform.translate = at;
            scene.objects.push_back(object);
        }
        const RenderedFrame frame = render_scene(*context, scene, {320, 256});
        std::pair<size_t, double> covered_ink{0, 0.0};
        for (size_t i = 0; i < frame.depth.size(); ++i)
            if (frame.depth[i] < 1.0f) ++covered_ink.first, covered_ink.second += 1.0 - frame.color.pixels[4 * i] / 255.0;
        covered_ink.second /= double(std::max<size_t>(covered_ink.first, 1));
        return covered_ink;
    };
    const auto near = draw("near.obj", {glm::vec3(0.0f)}), far_one = draw("far.obj", {glm::vec3(0.0f)});
    const auto near_pair = draw("near.obj", {glm::vec3(0.0f), glm::vec3(2.5f, 0.0f, 0.0f)});
    const auto far_pair = draw("far.obj", {glm::vec3(0.0f), glm::vec3(2.5f, 0.0f, 0.0f)});
    std::printf("near the origin: %zu covered, ink %.4f; 3e4 out: %zu, %.4f; pairs: %zu, %.4f against %zu, %.4f\n", near.first,
                near.second, far_one.first, far_one.second, near_pair.first, near_pair.second, far_pair.first, far_pair.second);
    EXPECT_GT(near.first, 20000u);
    EXPECT_NEAR(double(far_one.first), double(near.first), 0.01 * double(near.first));
    EXPECT_NEAR(far_one.second, near.second, 0.02 * near.second);
    EXPECT_NEAR(double(far_pair.first), double(near_pair.first), 0.01 * double(near_pair.first));
    EXPECT_NEAR(far_pair.second, near_pair.second, 0.02 * near_pair.second);
}

// A mirroring transform draws the model's mirror image: the same drawing as the mirror image stored in a file
// (it was refused; drawn with the model's own winding it came out inside out: the depth pass kept the far faces,
// the toon ramp and the contours read the normals reversed). An egg, wide on one side, so that a mirror is not
// the model; turned Z-up too (the up axis turns the model about its centre before the transform), mirrored there
// across the world's z = 0 plane, which the turn makes the file's y: a mirror that does not commute with the turn.
TEST_F(SceneObjects, AMirroringTransformDrawsTheMirrorImage) {
    auto dir = test::temp_dir("scene-mirror");
    Mesh egg = make_icosphere(4);
    for (glm::vec3& p : egg.positions) p = glm::vec3(p.x * (1.0f + 0.5f * std::max(p.x, 0.0f)), p.y, p.z + 0.3f * p.x * p.y);
    write_mesh_obj(dir, "egg.obj", egg);
    Mesh mirrored = egg;  // re-wound; across x = 0 (Y-up) or y = 0 (Z-up)
    for (size_t t = 0; t < mirrored.triangle_count(); ++t) std::swap(mirrored.indices[3 * t + 1], mirrored.indices[3 * t + 2]);
    write_mesh_obj(dir, "egg_mirrored_x.obj", mirrored, [](const glm::vec3& p) { return glm::vec3(-p.x, p.y, p.z); });
    write_mesh_obj(dir, "egg_mirrored_y.obj", mirrored, [](const glm::vec3& p) { return glm::vec3(p.x, -p.y, p.z); });
    struct Drawn {
        std::vector<uint8_t> covered;
        double ink = 0.0;   // mean darkness over the covered pixels
        size_t dark = 0;    // pixels darker than half (the lines)
    };
    auto draw = [&](const std::string& model, const Transform& transform, UpAxis up) {
        Scene scene;
        scene.base_dir = dir;
        SceneObject object;
        object.model = model;
        object.transform = transform;
        object.params.up = up;
        object.params.toon = true;
        object.params.contours = true;
        scene.objects = {object};
        scene.camera.yaw_deg = 35.0f, scene.camera.pitch_deg = 20.0f;
        const RenderedFrame frame = render_scene(*context, scene, {320, 256});
        Drawn d;
        size_t n = 0;
        for (size_t i = 0; i < frame.depth.size(); ++i) {
            d.covered.push_back(frame.depth[i] < 1.0f);
            if (!d.covered.back()) continue;
            d.ink += 1.0 - frame.color.pixels[4 * i] / 255.0, ++n;
            d.dark += frame.color.pixels[4 * i] < 128;
        }
        d.ink /= double(std::max<size_t>(n, 1));
        return d;
    };
    for (UpAxis up : {UpAxis::Y, UpAxis::Z}) {
        Transform by_scale;
        by_scale.translate = {0.2f, -0.1f, 0.3f};
        by_scale.rotate_deg = {0.0f, 20.0f, 0.0f};
        by_scale.axis_scale = up == UpAxis::Y ? glm::vec3(-1.0f, 1.0f, 1.0f) : glm::vec3(1.0f, 1.0f, -1.0f);
        Transform stored;
        stored.translate = by_scale.translate, stored.rotate_deg = by_scale.rotate_deg;
        ASSERT_TRUE(by_scale.mirrors() && !stored.mirrors());
        const std::string mirrored_file = up == UpAxis::Y ? "egg_mirrored_x.obj" : "egg_mirrored_y.obj";
        const Drawn reference = draw(mirrored_file, stored, up), mirror = draw("egg.obj", by_scale, up);
        const Drawn plain = draw("egg.obj", stored, up);
        size_t unlike = 0;
        for (size_t i = 0; i < reference.covered.size(); ++i) unlike += reference.covered[i] != plain.covered[i];
        EXPECT_GT(unlike, 1000u) << "the egg is its own mirror image";
        size_t both = 0, either = 0;
        for (size_t i = 0; i < mirror.covered.size(); ++i)
            both += mirror.covered[i] && reference.covered[i], either += mirror.covered[i] || reference.covered[i];
        std::printf("up %d: covered %zu of %zu either way; ink %.4f against %.4f; dark %zu against %zu\n", int(up), both,
                    either, mirror.ink, reference.ink, mirror.dark, reference.dark);
        EXPECT_GT(either, 8000u);
        // The outline's pixels may differ where dots reach past it: the two meshes have their own stipples.
        EXPECT_GE(double(both), 0.99 * double(either));
        EXPECT_NEAR(mirror.ink, reference.ink, 0.03 * reference.ink);
        EXPECT_NEAR(double(mirror.dark), double(reference.dark), 0.05 * double(reference.dark));
    }
}

// What the viewer met in review (2026-12-03): a dropped animated model on a scene drawn on the cpu path,
// which cannot draw it, took the splat path instead of leaving the scene with an object the renderer did
// not have (the next frame ended the viewer); stipples made for parameters the panel no longer asks for
// (set back while they were made) are not applied; a timeline at the end of an animation that does not
// loop plays again from the start.
TEST_F(SceneObjects, ViewerSceneTakesDropsAndResultsOnlyAsThePanelAsks) {
    auto dir = test::temp_dir("scene-live-drops");
    write_sphere_obj(dir);
    const std::string tube = test::write_rig(anim::rigs::bending_cylinder(), "scene-live-drops-rig", "tube");
    Scene scene;
    scene.base_dir = dir;
    scene.objects.push_back({"sphere.obj", {}, {}});
    scene.objects[0].params.generation.dmax = 0.02f;
    scene.objects[0].params.density_path = DensityPath::Cpu;
    SceneContent content = load_scene_content(scene);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    app::LiveScene live(scene, std::move(content), renderer);
    live.add_model(tube);
    ASSERT_EQ(live.size(), 2u);
    ASSERT_EQ(renderer.object_count(), 2u);
    EXPECT_EQ(live.scene().objects[1].params.density_path, ObjectParams{}.density_path);
    EXPECT_TRUE(live.sync(0.5).empty());
    EXPECT_EQ(renderer.params(1).density_path, ObjectParams{}.density_path);

    // Stipples for D_max 0.04 arrive after the panel was set back to 0.02: stale, not applied.
    const uint32_t before = renderer.object(0).geometry.stipple_count;
    GenerationParams asked = live.scene().objects[0].params.generation;
    asked.dmax = 0.04f;
    auto stale = make_stipples(live.model(0), asked);
    EXPECT_FALSE(live.apply_stipples(live.id(0), asked, stale,
                                     prepare_object_upload(*context, *live.model(0).mesh, *stale, asked.seed, {})));
    EXPECT_EQ(renderer.object(0).geometry.stipple_count, before);
    EXPECT_FALSE(live.generation_changed(0));
    live.scene().objects[0].params.generation.dmax = 0.04f;  // asked for now: applied
    EXPECT_TRUE(live.apply_stipples(live.id(0), asked, stale,
                                    prepare_object_upload(*context, *live.model(0).mesh, *stale, asked.seed, {})));
    EXPECT_NEAR(double(renderer.object(0).geometry.stipple_count), 2.0 * before, 0.02 * before);

    app::Timeline timeline;
    live.scene().objects[1].animation.loop = false;
    const double length = app::timeline_length(live.scene(), live.objects());
    ASSERT_GT(length, 0.0);
    timeline.advance(length + 1.0, live.scene(), live.objects());
    EXPECT_FALSE(timeline.playing()) << "the end holds";
    EXPECT_DOUBLE_EQ(timeline.time(), length);
    timeline.toggle_play(live.scene(), live.objects());
    EXPECT_TRUE(timeline.playing());
    EXPECT_DOUBLE_EQ(timeline.time(), 0.0) << "played from the end, it starts again";
    // With another object that loops the clock runs on (the one that does not holds its last pose, as render
    // draws it): it stopped at the end and froze the looping one too (until 2026-12-07).
    live.add_model(tube);
    ASSERT_EQ(live.size(), 3u);
    live.scene().objects[2].animation.loop = true;
    timeline.advance(length + 1.0, live.scene(), live.objects());
    EXPECT_TRUE(timeline.playing()) << "an object still loops";
    EXPECT_DOUBLE_EQ(timeline.time(), length + 1.0);
}

// A model the viewer draws already, dropped again: a copy sharing its mesh, stipples and GPU shape (each drop
// loaded the file again, held it anew and was charged as a new model). And what the viewer adds, a saved scene
// loads again: drops are checked beside the scene file's plan, not only what the device holds (the viewer took
// 748 copies whose saved file was then refused at objects[724]).
TEST_F(SceneObjects, ViewerSceneDropsOfAModelItDrawsAreCopiesThatASavedSceneHolds) {
    auto dir = test::temp_dir("scene-live-copies");
    const std::string sphere = write_sphere_obj(dir).string();
    Scene scene;
    scene.base_dir = dir;
    scene.objects.push_back({"sphere.obj", {}, {}});
    scene.objects[0].params.generation.dmax = 0.02f;
    const std::string saved = (dir / "saved.json").string();
    size_t added = 0;
    {
        SceneContent content = load_scene_content(scene);
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        app::LiveScene live(scene, std::move(content), renderer);
        live.add_model(sphere);
        ASSERT_EQ(live.size(), 2u);
        EXPECT_EQ(live.model(1).mesh, live.model(0).mesh);
        EXPECT_EQ(live.model(1).stipples, live.model(0).stipples);
        EXPECT_EQ(renderer.object(1).shape, renderer.object(0).shape);
        {  // The file rewritten since it was loaded (a model edited and exported again): loaded anew, not copied.
            const std::string text = test::slurp(sphere);
            const auto time = std::filesystem::last_write_time(sphere);
            write_text(sphere, text + "# edited\n");
            live.add_model(sphere);
            ASSERT_EQ(live.size(), 3u);
            EXPECT_NE(live.model(2).mesh, live.model(0).mesh);
            live.remove(2);
            write_text(sphere, text);
            std::filesystem::last_write_time(sphere, time);  // as loaded: copies again below
        }
        // Under a limit that holds a few dozen copies by the plan, drops until one is refused.
        const uint64_t copy = planned_object_bytes(*live.model(0).mesh, live.model(0).stipples->size(), true);
        const uint64_t plan = planned_scene_bytes(live.scene(), SceneContent{live.objects()});
        test::ScopedEnv limit("STIPPLE_GPU_MEMORY_LIMIT", std::to_string(plan + 30 * copy + copy / 2));
        bool refused = false;
        for (int i = 0; i < 200 && !refused; ++i) {
            try {
                live.add_model(sphere);
                ++added;
            } catch (const Error& e) {
                refused = true;
                EXPECT_NE(std::string(e.what()).find("of GPU memory"), std::string::npos) << e.what();
            }
        }
        EXPECT_TRUE(refused);
        std::printf("%zu copies added before a refusal (the plan holds 30)\n", added);
        EXPECT_GE(added, 10u);  // copies are cheap (30 by the plan; the blocks the device holds may take a few)
        EXPECT_LE(added, 30u);  // never more than the plan holds
        live.save(saved, OrbitCamera{});
    }
    // The renderer gone, the saved scene's plan holds under the same limit.
    const Scene again = load_scene(saved);
    ASSERT_EQ(again.objects.size(), added + 2);
    const SceneContent content = load_scene_content(again);
    const uint64_t copy = planned_object_bytes(*content.objects[0].mesh, content.objects[0].stipples->size(), true);
    Scene first = again;
    first.objects.resize(2);
    SceneContent first_content;
    first_content.objects.assign(content.objects.begin(), content.objects.begin() + 2);
    const uint64_t plan = planned_scene_bytes(first, first_content);
    test::ScopedEnv limit("STIPPLE_GPU_MEMORY_LIMIT", std::to_string(plan + 30 * copy + copy / 2));
    EXPECT_NO_THROW(check_scene_fits(*context, again, content));
}

TEST_F(SceneObjects, ViewerSceneAddsDroppedModelsAndRegeneratesOnCommit) {
    // What the viewer does with a drop and with the panel's generation parameters, without a window.
    auto dir = test::temp_dir("scene-live");
    std::string sphere = write_sphere_obj(dir).string();
    write_text(dir / "broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    Scene scene;
    scene.base_dir = dir;
    scene.objects.push_back({"sphere.obj", {}, {}});
    scene.objects[0].params.generation.dmax = 0.02f;
    SceneContent content = load_scene_content(scene);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    app::LiveScene live(scene, std::move(content), renderer);
    ASSERT_EQ(renderer.object_count(), 1u);

    // Bad drops are errors to report; nothing changes.
    for (std::string bad : {(dir / "broken.obj").string(), (dir / "missing.obj").string(), (dir / "x.json").string()})
        EXPECT_THROW(live.add_model(bad), Error) << bad;
    EXPECT_EQ(renderer.object_count(), 1u);
    EXPECT_EQ(live.size(), 1u);

    // A good one lands beside the others, at the first one's size.
    Sphere before = live.bounds();
    live.add_model(sphere);
    ASSERT_EQ(renderer.object_count(), 2u);
    Sphere a = transform_sphere(compute_bounding_sphere(make_icosphere(4)), live.scene().objects[0].transform.to_matrix());
    Sphere b = transform_sphere(compute_bounding_sphere(make_icosphere(4)), live.scene().objects[1].transform.to_matrix());
    EXPECT_GT(glm::length(a.center - b.center), a.radius + b.radius) << "the dropped model overlaps the scene";
    EXPECT_NEAR(b.radius, a.radius, 1e-3f);
    EXPECT_GT(live.bounds().radius, 1.5f * before.radius);

    // D_max acts when committed, on that object only, and the objects keep their order.
    uint32_t first = renderer.object(0).geometry.stipple_count, second = renderer.object(1).geometry.stipple_count;
    live.scene().objects[0].params.generation.dmax = 0.04f;
    live.sync();
    EXPECT_EQ(renderer.object(0).geometry.stipple_count, first) << "regenerated before the edit was committed";
    EXPECT_TRUE(live.regenerate_if_changed(0));
    EXPECT_FALSE(live.regenerate_if_changed(1));
    EXPECT_NEAR(double(renderer.object(0).geometry.stipple_count), 2.0 * first, 0.02 * first);
    EXPECT_EQ(renderer.object(1).geometry.stipple_count, second);
    // The rebuilt renderer still draws both (sparse at these densities: a few hundred dots).
    OffscreenTarget target(*context, {480, 360});
    live.sync();
    OrbitCamera camera = resolve_camera(live.scene().camera, live.bounds(), 480.0f / 360.0f);
    EXPECT_GT(test::measure_ink(target.render(renderer, scene_frame_view(live.scene(), camera, live.bounds(), {480, 360})))
                  .inked_inside,
              100u);

    // Saved as the viewer's Ctrl+S does: both objects, the new D_max, the viewer's camera.
    camera.yaw_deg = 33.0f;
    live.save((dir / "saved.json").string(), camera);
    Scene saved = load_scene((dir / "saved.json").string());
    ASSERT_EQ(saved.objects.size(), 2u);
    EXPECT_FLOAT_EQ(saved.objects[0].params.generation.dmax, 0.04f);
    EXPECT_FLOAT_EQ(saved.camera.yaw_deg, 33.0f);
    live.remove(1);
    live.remove(0);  // the last object stays
    EXPECT_EQ(renderer.object_count(), 1u);
}

struct BadScene {
    const char* name;
    const char* json;
    const char* field;    // expected in the message
    const char* problem;  // expected in the message
};

// A failing case is named by its name, not printed as "32-byte object <...>".
void PrintTo(const BadScene& bad, std::ostream* out) { *out << bad.name; }

class BadSceneFile : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, OneLineNamingFileFieldAndProblem) {
    const BadScene& bad = GetParam();
    auto dir = test::temp_dir(std::string("scene-bad-") + bad.name);
    write_sphere_obj(dir);
    write_text(dir / "broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    std::string file = (dir / "scene.json").string();
    write_text(file, bad.json);

    // The library: load (and, for a broken model, load the content) throws one line.
    std::string message;
    try {
        load_scene_content(load_scene(file));
    } catch (const Error& e) {
        message = e.what();
    }
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(bad.field), std::string::npos) << message;
    EXPECT_NE(message.find(bad.problem), std::string::npos) << message;

    // The command line: render and view fail before drawing or opening a window, exit 1, one line.
    for (const char* command : {"render", "view"}) {
        std::vector<std::string> args{command, file};
        if (std::string(command) == "render") args.insert(args.end(), {"-o", (dir / "out.png").string()});
        auto result = test::run_stipple(args);
        EXPECT_EQ(result.exit_code, 1) << command << ": " << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_NE(result.err.find(file), std::string::npos) << result.err;
        EXPECT_NE(result.err.find(bad.field), std::string::npos) << result.err;
        EXPECT_NE(result.err.find(bad.problem), std::string::npos) << result.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadSceneFile,
    ::testing::Values(
        BadScene{"not_json", "{\"objects\": [ {\"model\": ", "not valid JSON", "parse error"},
        BadScene{"not_an_object", "[1, 2, 3]", "scene.json: expected an object", "got array"},
        BadScene{"wrong_type", R"({"objects": [{"model": "sphere.obj", "params": {"dmax": "dark"}}]})",
                 "objects[0].params.dmax", "expected a number, got string"},
        // Finite, but beyond a float: said so (it said "not finite").
        BadScene{"beyond_float", R"({"objects": [{"model": "sphere.obj", "params": {"dmax": 1e300}}]})",
                 "objects[0].params.dmax", "1e+300 is beyond single precision (3.4e+38)"},
        BadScene{"wrong_type_vector", R"({"objects": [{"model": "sphere.obj"}], "light": [1, 2]})", "light",
                 "expected an array of 3 numbers"},
        BadScene{"unknown_param", R"({"objects": [{"model": "sphere.obj", "params": {"dmx": 0.2}}]})",
                 "objects[0].params.dmx", "unknown field"},
        BadScene{"unknown_top_level", R"({"objects": [{"model": "sphere.obj"}], "lights": [1, 1, 1]})", "lights",
                 "unknown field"},
        // A key of 100 characters is cut short in the message (one of a megabyte made a message of a megabyte).
        BadScene{"long_unknown_key", R"({"objects": [{"model": "sphere.obj"}], "kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk": 1})",
                 "kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk...: unknown field", "expected one of"},
        BadScene{"missing_model_field", R"({"objects": [{"params": {}}]})", "objects[0].model",
                 "required field is missing"},
        BadScene{"missing_model_file", R"({"objects": [{"model": "sphere.obj"}, {"model": "nowhere.obj"}]})",
                 "objects[1].model", "no such model file"},
        BadScene{"broken_model", R"({"objects": [{"model": "broken.obj"}]})", "objects[0].model", "broken.obj"},
        BadScene{"model_is_a_folder", R"({"objects": [{"model": "."}]})", "objects[0].model", "is a directory, not a model file"},
        BadScene{"model_is_a_device", R"({"objects": [{"model": "/dev/null"}]})", "objects[0].model", "is not a regular file"},
        BadScene{"out_of_range", R"({"objects": [{"model": "sphere.obj"}, {"model": "sphere.obj", "params": {"dmax": 20}}]})",
                 "objects[1].params.dmax", "out of range"},
        BadScene{"negative_integer", R"({"objects": [{"model": "sphere.obj", "params": {"seed": -3}}]})",
                 "objects[0].params.seed", "out of range"},
        // Refused as --dmax refuses it (it was read as a float, 0, and drew nothing).
        BadScene{"underflowing_float", R"({"objects": [{"model": "sphere.obj", "params": {"dmax": 1e-46}}]})",
                 "objects[0].params.dmax", "1e-46 is out of range: it must be >= 0 and <= 16 (single precision holds it as 0: give 0, or at least 1e-38)"},
        BadScene{"bad_enum", R"({"objects": [{"model": "sphere.obj", "params": {"density_path": "gpu"}}]})",
                 "objects[0].params.density_path", "'gpu' is not one of vertex, cpu"},
        BadScene{"bad_scale", R"({"objects": [{"model": "sphere.obj", "transform": {"scale": -1}}]})",
                 "objects[0].transform.scale", "must be in [1e-6, 1e6]"},
        BadScene{"tiny_scale", R"({"objects": [{"model": "sphere.obj", "transform": {"scale": 1e-16}}]})",
                 "objects[0].transform.scale", "must be in [1e-6, 1e6]"},
        BadScene{"singular_matrix", R"({"objects": [{"model": "sphere.obj", "transform": {"matrix":
                 [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1]}}]})",
                 "objects[0].transform.matrix", "singular"},
        BadScene{"flat_matrix", R"({"objects": [{"model": "sphere.obj", "transform": {"matrix":
                 [1,0,0,0, 1,1e-9,0,0, 0,0,1,0, 0,0,0,1]}}]})",
                 "objects[0].transform.matrix", "singular"},
        BadScene{"zero_axis_scale", R"({"objects": [{"model": "sphere.obj", "transform": {"scale": [-1, 0, 1]}}]})",
                 "objects[0].transform.scale", "the y axis's scale 0 must be in [1e-6, 1e6], or in [-1e6, -1e-6]"},
        BadScene{"huge_matrix", R"({"objects": [{"model": "sphere.obj", "transform": {"matrix":
                 [1e20,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}]})",
                 "objects[0].transform.matrix", "column 0 scales its axis by 1e+20"},
        BadScene{"bad_colour", R"({"objects": [{"model": "sphere.obj"}], "paper": [1, 2, 0]})", "paper", "0..1"},
        BadScene{"paused_not_a_boolean", R"({"objects": [{"model": "sphere.obj"}], "paused": "yes"})", "paused", "expected true or false"},
        BadScene{"bad_object_ink", R"({"objects": [{"model": "sphere.obj"}, {"model": "sphere.obj", "ink": [0, 0, 1.5]}]})",
                 "objects[1].ink", "0..1"},
        BadScene{"bad_camera", R"({"objects": [{"model": "sphere.obj"}], "camera": {"distance": 0}})",
                 "camera.distance", "must be in"},
        BadScene{"bad_projection", R"({"objects": [{"model": "sphere.obj"}], "camera": {"projection": "isometric"}})",
                 "camera.projection", "must be \"perspective\" or \"orthographic\""},
        BadScene{"empty_objects", R"({"objects": []})", "objects", "no objects"},
        // JSON allows a repeated key but not which one counts: the parser kept the last silently.
        BadScene{"repeated_param", R"({"objects": [{"model": "sphere.obj", "params": {"dmax": 20, "dmax": 0.1}}]})",
                 "objects[0].params.dmax", "the field is given twice"},
        BadScene{"repeated_objects", R"({"objects": [{"model": "sphere.obj"}], "objects": []})", "objects",
                 "the field is given twice"},
        BadScene{"alias_and_switch", R"({"objects": [{"model": "sphere.obj", "params": {"silhouette_lines": false,
                 "silhouette": "both"}}]})", "objects[0].params.silhouette", "sets silhouette_lines too"},
        BadScene{"camera_path_yaw", R"({"objects": [{"model": "sphere.obj"}], "camera_path": [{"yaw": 3e38}, {"yaw": -3e38}]})",
                 "camera_path[0].yaw", "must be in -36000..36000 degrees"},
        BadScene{"no_objects", R"({"camera": {"yaw": 3}})", "objects", "required field is missing"},
        // Places beyond the coordinates drawing allows drew a blank frame with exit status 0.
        BadScene{"huge_translate", R"({"objects": [{"model": "sphere.obj", "transform": {"translate": [3e38, 0, 0]}}]})",
                 "objects[0].transform.translate", "components must be within -1e+18..1e+18"},
        BadScene{"huge_matrix_translation", R"({"objects": [{"model": "sphere.obj", "transform": {"matrix":
                 [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,-3e38,0,1]}}]})",
                 "objects[0].transform.matrix", "the translation (elements 12-14) must be within"},
        BadScene{"huge_target", R"({"objects": [{"model": "sphere.obj"}], "camera": {"target": [3e38, -3e38, 3e38]}})",
                 "camera.target", "components must be within"},
        BadScene{"tiny_world_distance", R"({"objects": [{"model": "sphere.obj"}], "camera": {"world_distance": 1e-38}})",
                 "camera.world_distance", "must be in 1e-21..1e+24"}),
    [](const auto& info) { return std::string(info.param.name); });

// Options that would be silently dropped are refused: the camera's with a camera_path (which places
// every frame's camera), and the old --silhouette with the switches it sets.
TEST(Scene, OptionsThatWouldBeIgnoredAreRefused) {
    auto dir = test::temp_dir("scene-ignored-options");
    write_sphere_obj(dir);
    write_text(dir / "path.json", R"({"objects": [{"model": "sphere.obj"}], "camera_path": [{"yaw": 0}, {"yaw": 90}]})");
    for (const char* option : {"--yaw", "--pitch", "--distance"}) {
        auto result = test::run_stipple({"render", (dir / "path.json").string(), option, "3", "-o", (dir / "out.png").string()});
        EXPECT_EQ(result.exit_code, 1) << option;
        EXPECT_NE(result.err.find(std::string(option) + " sets the camera, but the scene's camera_path"), std::string::npos)
            << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    auto orbit = test::run_stipple({"render", (dir / "path.json").string(), "--frames", "2", "--orbit", "90", "-o",
                                    (dir / "out%d.png").string()});
    EXPECT_EQ(orbit.exit_code, 1);
    EXPECT_NE(orbit.err.find("--orbit sets the camera"), std::string::npos) << orbit.err;

    auto alias = test::run_stipple({"render", (dir / "sphere.obj").string(), "--silhouette-lines", "--silhouette", "none", "-o",
                                    (dir / "out.png").string()});
    EXPECT_EQ(alias.exit_code, 1);
    EXPECT_NE(alias.err.find("--silhouette sets --silhouette-lines too"), std::string::npos) << alias.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(Scene, ObjectOptionsAreNotMixedWithASceneFile) {
    auto dir = test::temp_dir("scene-mixed-options");
    write_sphere_obj(dir);
    write_text(dir / "scene.json", R"({"objects": [{"model": "sphere.obj"}]})");
    auto result = test::run_stipple({"render", (dir / "scene.json").string(), "--dmax", "0.3", "-o",
                                     (dir / "out.png").string()});
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("--dmax cannot be combined with a scene file"), std::string::npos) << result.err;
}

TEST(Scene, ASceneOfOneModelRendersLikeTheModel) {
    // `render SCENE.json` and `render MODEL` share one path: a scene holding the default model with
    // default parameters and camera draws exactly the image of `render` with that model.
    auto dir = test::temp_dir("scene-vs-model");
    std::string model = test::source_path("assets/blobby.glb");
    write_text(dir / "scene.json", "{\"objects\": [{\"model\": \"" + model + "\"}]}");
    auto a = test::run_stipple({"render", (dir / "scene.json").string(), "-o", (dir / "scene.png").string(),
                                "--width", "480", "--height", "360", "--yaw", "25"});
    auto b = test::run_stipple({"render", model, "-o", (dir / "model.png").string(), "--width", "480", "--height", "360",
                                "--yaw", "25"});
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_EQ(read_text(dir / "scene.png"), read_text(dir / "model.png"));
}

}  // namespace
}  // namespace stipple
