// Tone across scale, the paper's central claim (§2.3, Figures 3-6; issue 18): with the extrinsic
// enhancement an object keeps its tone as it moves away, on every model, on a mesh mixing tiny and large
// polygons, at any image size. The figure is the mean ink inside the coverage mask from full frame height
// down to 1/16 of it (src/render/tone_survey.hpp, also `stipple tone`), measured through a narrow field of
// view so that the same surface stays in view (at 30 degrees perspective alone changes what is seen, see
// docs/paper-reading.md), at two elevations, each averaged over 16 yaws all around the object.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "mesh/primitives.hpp"
#include "render/tone_survey.hpp"
#include "stipple/object_data.hpp"
#include "support/gpu_test.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

struct ToneCase {
    // A file of ../shared/models, "blobby.glb" (the default scene), "mixed_sphere", "cad_cylinder",
    // "cad_cylinder_1024" or "cad_cylinder_tilted".
    const char* model;
    uint32_t width, height;
    // The largest max/min allowed with the enhancement on: the 1.05, or (known gaps, issue 18)
    // the figure measured on this branch with a small margin, so that a regression still fails; 0 where
    // the figure is printed only (see the case).
    double limit = 1.05;
    float dmax = 0.0f;  // D_max; 0: the default
    // Seeds 1..seeds, each distance's ink averaged over them (mean_survey): where an object draws so few
    // dots at 1/16 that which ones a seed draws moves the figure by several percent (`stipple tone` prints
    // that bound), their mean is the tone and one seed's figure mostly its sampling noise.
    int seeds = 1;
    bool orthographic = false;  // parallel lines of sight (the same surface at every distance, only the scale changes)
    bool coarse_class = false;  // the quarter generated as a class of its own (stipple_classes.hpp)
    DensityPath path = ObjectParams{}.density_path;
};

void PrintTo(const ToneCase& c, std::ostream* os) {
    *os << c.model << " " << c.width << "x" << c.height;
    if (c.dmax > 0.0f) *os << " D_max " << c.dmax;
    if (c.orthographic) *os << " orthographic";
    if (c.coarse_class) *os << " coarse class";
    if (c.path != ObjectParams{}.density_path) *os << " " << density_path_name(c.path) << " path";
}

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class ToneAcrossScale : public test::GpuTest, public ::testing::WithParamInterface<ToneCase> {};

struct Subject {
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const StippleSet> stipples;
    Sphere bounds;
    anim::Motion motion;  // an animated model is drawn as render draws it (its first animation at 0 s)
};

// The model as the commands draw it, its stipples from the cache; empty mesh when the file is absent.
Subject load_subject(const std::string& name, const GenerationParams& generation) {
    Subject s;
    if (name == "mixed_sphere" || name == "cad_cylinder" || name == "cad_cylinder_1024" || name == "cad_cylinder_tilted") {
        // mixed_sphere: the northern hemisphere in a few large triangles, the southern one in many tiny
        // ones (about 700 times smaller), joined by slivers: a CAD part's or a partly simplified scan's
        // mix. cad_cylinder: large slivers only, 40 times longer than wide, which stay in the large regime
        // at 1/16 of the size and draw there the first 1/400 to 1/1000 of their stipples. cad_cylinder_1024:
        // slivers 650 times longer than wide, side by side, and caps of 1024-blade fans; tilted, the same
        // turned so that its slivers lie along no axis (40 degrees about z, then 25 about x).
        Mesh mesh = name == "mixed_sphere" ? make_mixed_sphere(3, 100)
                    : name == "cad_cylinder" ? make_cad_cylinder(64)
                                             : make_cad_cylinder(1024);
        if (name == "cad_cylinder_tilted") {
            const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(25.0f), glm::vec3(1, 0, 0)) *
                                             glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(0, 0, 1)));
            for (glm::vec3& p : mesh.positions) p = turn * p;
            for (glm::vec3& n : mesh.normals) n = turn * n;
        }
        s.mesh = std::make_shared<const Mesh>(std::move(mesh));
        s.stipples = make_stipples(*s.mesh, generation);
        s.bounds = compute_bounding_sphere(*s.mesh);
        return s;
    }
    const std::string path =
        name == "blobby.glb" ? test::source_path("assets/blobby.glb") : test::shared_model(name);
    if (path.empty()) return s;
    ObjectData data = load_object_data(path, generation);
    s.mesh = data.mesh;
    s.stipples = data.stipples;
    s.bounds = data.bounds;
    s.motion = data.motion;
    return s;
}

ToneSurveyOptions survey_options(VkExtent2D extent) {
    ToneSurveyOptions options;
    options.extent = extent;
    // Two elevations, each all around the object: 16 yaws, the same at every distance. At 1/16 of the
    // frame height an object draws ~150 stipples; one view's tone is then off by ~6% (sd over views, a
    // fixed selection per polygon for frame coherence), and nearby angles share the error.
    options.views = {{30.0f, 10.0f}, {30.0f, -15.0f}};
    options.frames = 16;
    options.arc_deg = 360.0f;
    options.fov_y_deg = 4.0f;
    return options;
}

void print_survey(const char* name, const ToneSurvey& survey, const ToneSurveyOptions& options, const char* extrinsic,
                  const std::string& which = "") {
    for (size_t v = 0; v < options.views.size(); ++v) {
        std::printf("%s%s %ux%u, view %g:%g, extrinsic %s: mean ink", which.c_str(), name, options.extent.width,
                    options.extent.height, options.views[v][0], options.views[v][1], extrinsic);
        for (const ToneSample& s : survey.samples) std::printf(" %.4f", s.mean_ink[v]);
        std::printf("  -> max/min %.3f\n", survey.max_over_min(v));
    }
}

TEST_P(ToneAcrossScale, HoldsOverASixteenfoldRangeOfSize) {
    const ToneCase c = GetParam();
    ObjectParams params;
    if (c.dmax > 0.0f) params.generation.dmax = c.dmax;
    params.generation.coarse_class = c.coarse_class;
    params.density_path = c.path;
    std::vector<ToneSurvey> seed_surveys;
    ToneSurvey off;
    for (int seed = 1; seed <= c.seeds; ++seed) {
        params.generation.seed = uint64_t(seed);
        const Subject subject = load_subject(c.model, params.generation);
        if (!subject.mesh) GTEST_SKIP() << "../shared/models/" << c.model << " is absent";
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        // With its motion: without it the fox's stretch headroom was drawn as rest density (until 2026-12-04).
        renderer.add_object(*subject.mesh, *subject.stipples, glm::mat4(1.0f), params, subject.motion);

        ToneSurveyOptions options = survey_options({c.width, c.height});
        options.orthographic = c.orthographic;
        seed_surveys.push_back(survey_tone(*context, renderer, 0, subject.bounds, options));
        print_survey(c.model, seed_surveys.back(), options, "on ",
                     c.seeds > 1 ? "seed " + std::to_string(seed) + ": " : "");
        if (seed > 1) continue;
        renderer.params(0).extrinsic = false;
        options.frames = 4;
        off = survey_tone(*context, renderer, 0, subject.bounds, options);
    }
    const ToneSurveyOptions options = survey_options({c.width, c.height});
    const ToneSurvey on = mean_survey(seed_surveys);
    if (c.seeds > 1) print_survey(c.model, on, options, "on ", "mean of seeds 1-" + std::to_string(c.seeds) + ": ");
    print_survey(c.model, off, options, "off");

    if (c.limit > 0.0) {
        EXPECT_LE(on.worst_max_over_min(), c.limit) << c.model << ": the tone drifts with the object's size";
    }
    // At 640x512 the framed object is already dark without the enhancement (0.85): 1.17 measured.
    EXPECT_GT(off.worst_max_over_min(), 1.1) << "without the enhancement a smaller object should darken clearly";
}

INSTANTIATE_TEST_SUITE_P(
    Models, ToneAcrossScale,
    ::testing::Values(ToneCase{"stanford-bunny.obj", 1280, 1024}, ToneCase{"igea.ply", 1280, 1024}, ToneCase{"spot.obj", 1280, 1024},
                      ToneCase{"blobby.glb", 1280, 1024}, ToneCase{"mixed_sphere", 1280, 1024},
                      // 1.081 / 1.104 (seed 1) while the progressive order searched for placed stipples
                      // within 12 spacings only, which left the prefixes below 1/256 unspread.
                      ToneCase{"cad_cylinder", 1280, 1024},
                      // 1024 slivers 650 times longer than wide. Until 2026-12-05 the progressive order's slabs
                      // lay across the longest axis and cut every sliver into pieces, ordered apart: at a
                      // distance neighbours' single dots fell on each other (the mean of seeds 1-3 read
                      // 1.111 / 1.109, 10% lighter at 1/8; with every sliver taking its first stipples from
                      // the same pieces, until 2026-12-04, 1.282 / 1.179 for seed 1). Slabs along the
                      // slivers leave them whole: 1.029 / 1.039 (progressive_order.cpp, make_units).
                      ToneCase{"cad_cylinder_1024", 1280, 1024, 1.05, 0.0f, 3},
                      // Slivers along no axis: slabs across the direction the cut triangles share
                      // (progressive_order.cpp). 1.036 / 1.050 (seeds 1-3; with slabs across an axis, as an
                      // OBJ through `stipple tone`: 1.089 / 1.085, against 1.035 / 1.048 now).
                      ToneCase{"cad_cylinder_tilted", 1280, 1024, 1.06, 0.0f, 3},
                      ToneCase{"stanford-bunny.obj", 2560, 2048},
                      // At 640x512 the bunny at 1/16 is 32 pixels high and draws about 560 dots over the 16
                      // frames: one seed's figure is 1.02-1.07 (seeds 1-3 of cache format 12; `stipple tone
                      // --width 640 --height 512 --seeds 1,2,3`, which bounds its noise at 4.2%), the mean of
                      // the seeds 1.020 / 1.042.
                      ToneCase{"stanford-bunny.obj", 640, 512, 1.05, 0.0f, 3},
                      // Four times the default density (2M candidates): 1.013 / 1.025 measured. At a low
                      // D_max the far figure is the noise of a few dozen dots (0.1: 1.01-1.08 over seeds 1-4,
                      // the seed-averaged ink flat within 3%; docs/paper-reading.md).
                      ToneCase{"stanford-bunny.obj", 1280, 1024, 1.05, 1.0f},
                      ToneCase{"horse.ply", 1280, 1024},
                      // Orthographic (beyond the paper): the eye ray +z and the scale the same at every depth in
                      // every term. 1.019 / 1.009 measured for the bunny, the default scene 1.030 /
                      // 1.017, 2026-12-06.
                      ToneCase{"stanford-bunny.obj", 1280, 1024, 1.05, 0.0f, 1, true},
                      ToneCase{"blobby.glb", 1280, 1024, 1.05, 0.0f, 1, true},
                      // The fox's 576 polygons leave only ~1,000 stipples at 1/16, so one seed's figure is
                      // mostly which ones it draws: 1.01-1.10 over seeds 1-3 (cache format 15), their mean
                      // 1.030 / 1.046 (format 14: 1.039 / 1.040; 13: 1.045 / 1.047; drawn without its motion,
                      // as until 2026-12-04, 1.014 / 1.017). Its large polygons stay in the large regime there and draw
                      // the first 1/400-1/1000 of their lists: with the progressive order's search at 12
                      // spacings (cache format 12) those prefixes were unspread, and the mean read 1.027 /
                      // 1.049, a real loss of 4-5% at 1/16 (docs/paper-reading.md, §2.1 "Order").
                      ToneCase{"fox.glb", 1280, 1024, 1.05, 0.0f, 3},
                      // 12 triangles of ~68k candidates each: thousands of stipples per polygon when framed
                      // (the splat's work items, kSplatChunk).
                      ToneCase{"AnimatedMorphCube.gltf", 1280, 1024},
                      // The ogre's far figure is 3-7% darker: 1.035 / 1.037 for this seed (cache format 17;
                      // 1.020 / 1.044 for 16), 1.036 for format 13 (1.040 for format 12, 1.054 before); the mean
                      // of seeds 1-3 1.034 / 1.036 (format 16: 1.027 / 1.041); seeds 2 and 3 gave 1.074 and 1.046
                      // for format 12 (1.069 and 1.042; issue 18: 1.077 and 1.062 before; dots
                      // spread more evenly at middle distances since polygons
                      // are selected by their first stipples, so they overlap less and the far ink gains). Per
                      // regime it draws what it owes (`stipple tone --regimes`: drawn/owed 0.99-1.00);
                      // the extra ink follows the depth pass's slope-scaled polygon offset, which lets
                      // more drawn stipples through at 1/16 (ink per drawn stipple 0.80 against 0.77
                      // framed; with half the slope bias it is flat, 0.72-0.73, and the figure 1.035,
                      // but 6% of the ink is then lost at every size to the dots' own surface): most
                      // likely surfaces just behind its many occluding parts, a band of constant pixel
                      // width whose share grows as the object shrinks.
                      ToneCase{"ogre.obj", 1280, 1024, 1.05},
                      // With the coarse class (off by default), whose prefixes are spread otherwise below and
                      // at a quarter: the scanned models of few stipples a polygon, where it takes effect.
                      ToneCase{"stanford-bunny.obj", 1280, 1024, 1.05, 0.0f, 1, false, true},
                      ToneCase{"igea.ply", 1280, 1024, 1.05, 0.0f, 1, false, true},
                      ToneCase{"horse.ply", 1280, 1024, 1.05, 0.0f, 1, false, true},
                      // The points pipeline (the paper's vertex path) on the thin-legged horse: its dots astride
                      // the outline clipped there, it read 1.061 / 1.061 (6% lighter at 1/16) until they were moved
                      // onto the surface (stipple.vert, outline_shift): 1.016 / 1.011, as the splat's 1.006 / 1.022.
                      ToneCase{"horse.ply", 1280, 1024, 1.05, 0.0f, 1, false, false, DensityPath::Vertex}),
    [](const ::testing::TestParamInfo<ToneCase>& info) {
        std::string name = info.param.model;
        name = name.substr(0, name.find('.'));
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "_" + std::string&&.
        name += '_';
        name += std::to_string(info.param.width);
        name += 'x';
        name += std::to_string(info.param.height);
        if (info.param.dmax > 0.0f) {
            name += "_dmax";
            name += std::to_string(int(std::lround(info.param.dmax * 100.0f)));
        }
        if (info.param.orthographic) name += "_orthographic";
        if (info.param.coarse_class) name += "_coarse_class";
        if (info.param.path != ObjectParams{}.density_path) {
            name += '_';
            name += density_path_name(info.param.path);
        }
        return name;
    });

// Per regime, the stipples drawn against the ink owed (tally_tone, the formulas every path uses), summed
// over views around the mixed sphere: probabilistic selection draws what its polygons owe on a mesh of
// tiny and large polygons alike (ranked values alone drew 1.4 times the owed ink on the ogre when framed).
TEST_F(ToneAcrossScale, EveryRegimeDrawsTheInkItOwesOnAMixedMesh) {
    ObjectParams params;
    const Subject subject = load_subject("mixed_sphere", params.generation);
    StippleRenderer renderer(*context, kColorFormat, context->depth_format);
    renderer.add_object(*subject.mesh, *subject.stipples, glm::mat4(1.0f), params);
    const VkExtent2D extent{1280, 1024};
    const float aspect = 1.25f;
    for (float distance : {1.0f, 4.0f, 16.0f}) {
        RegimeTally large, probabilistic;
        for (int v = 0; v < 24; ++v) {
            FrameView view;
            view.extent = extent;
            view.camera = camera_matrices(frame_sphere(subject.bounds, aspect, distance, 15.0f * v, 40.0f * std::sin(1.7f * v)),
                                          aspect, subject.bounds);
            renderer.prepare(view);  // the uniforms only: nothing is drawn
            const ToneTally tally = tally_tone(renderer.object(0), renderer.frame_uniforms());
            for (auto [to, from] : {std::pair{&large, ToneRegime::Large}, std::pair{&probabilistic, ToneRegime::Probabilistic}}) {
                const RegimeTally& r = tally.regimes[size_t(from)];
                to->polygons += r.polygons;
                to->owed += r.owed;
                to->drawn += r.drawn;
            }
        }
        std::printf("mixed sphere at %gx: large regime %zu polygons, drawn/owed %.4f; probabilistic %zu polygons, "
                    "drawn/owed %.4f (%.0f owed)\n",
                    distance, large.polygons, large.drawn / large.owed, probabilistic.polygons,
                    probabilistic.drawn / probabilistic.owed, probabilistic.owed);
        EXPECT_NEAR(large.drawn / large.owed, 1.0, 0.01);
        ASSERT_GT(probabilistic.owed, 500.0);
        EXPECT_NEAR(probabilistic.drawn / probabilistic.owed, 1.0, 0.03);
    }
}

}  // namespace
}  // namespace stipple
