// The viewer's camera arithmetic (app/camera_control.hpp), without a window: "frame all" fits the scene into
// the columns the open panel leaves free, and centres it there.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "app/camera_control.hpp"

namespace {

using namespace stipple;

// The normalised device x and y extent of points on the sphere's surface as `camera` sees them.
struct Extent {
    float left = 1e9f, right = -1e9f, bottom = 1e9f, top = -1e9f;
};
Extent projected(const OrbitCamera& camera, const Sphere& sphere, float aspect) {
    const CameraMatrices m = camera_matrices(camera, aspect, sphere);
    std::mt19937 random(7);
    std::normal_distribution<float> normal;
    Extent e;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p = sphere.center + sphere.radius * glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
        const glm::vec4 clip = m.proj * m.view * glm::vec4(p, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        e.left = std::min(e.left, ndc.x), e.right = std::max(e.right, ndc.x);
        e.bottom = std::min(e.bottom, ndc.y), e.top = std::max(e.top, ndc.y);
    }
    return e;
}

TEST(AppCamera, FrameAllFitsTheSceneIntoTheColumnsThePanelLeaves) {
    const Sphere sphere{glm::vec3(3.0f, -1.0f, 2.0f), 2.5f};
    const float aspect = 1280.0f / 1024.0f;
    struct Case {
        glm::vec2 free;
        float pitch;
    };
    for (const Case c : {Case{{0.0f, 1.0f}, -20.0f}, Case{{0.375f, 1.0f}, -20.0f}, Case{{0.0f, 0.6f}, -20.0f},
                         Case{{0.375f, 1.0f}, 89.0f}, Case{{0.25f, 0.5f}, -89.0f}})
    for (const bool orthographic : {false, true}) {
        const glm::vec2 free = c.free;
        OrbitCamera camera;
        camera.yaw_deg = 35.0f;
        camera.pitch_deg = c.pitch;
        camera.orthographic = orthographic;
        app::frame_all(camera, sphere, aspect, free);
        const Extent e = projected(camera, sphere, aspect);
        const float left = 2.0f * free.x - 1.0f, right = 2.0f * free.y - 1.0f;
        std::printf("%s, pitch %.0f, free columns %.3f..%.3f: the sphere spans x %.3f..%.3f (room %.3f..%.3f), y %.3f..%.3f\n",
                    orthographic ? "orthographic" : "perspective", c.pitch, free.x, free.y, e.left, e.right, left, right,
                    e.bottom, e.top);
        // Inside the free columns and the window's height, and filling one of the two (framing_distance).
        EXPECT_GE(e.left, left - 0.01f);
        EXPECT_LE(e.right, right + 0.01f);
        EXPECT_GE(e.bottom, -1.01f);
        EXPECT_LE(e.top, 1.01f);
        EXPECT_GT(std::max((e.right - e.left) / (right - left), (e.top - e.bottom) / 2.0f), 0.9f);
        // In the middle of them.
        EXPECT_NEAR(0.5f * (e.left + e.right), 0.5f * (left + right), 0.03f);
        // Orbiting turns about the scene's centre, which stays where it is on screen, and the scene within the free
        // columns (the target moved aside until 2026-12-06 swung the scene across the window as it turned).
        for (const float yaw : {40.0f, -75.0f, 180.0f}) {
            OrbitCamera turned = camera;
            app::orbit_degrees(turned, yaw, 0.0f);
            const CameraMatrices m = camera_matrices(turned, aspect, sphere);
            const glm::vec4 centre = m.proj * m.view * glm::vec4(sphere.center, 1.0f);
            EXPECT_NEAR(centre.x / centre.w, 0.5f * (left + right), 1e-4f) << "turned by " << yaw;
            const Extent t = projected(turned, sphere, aspect);
            EXPECT_GE(t.left, left - 0.01f) << "turned by " << yaw;
            EXPECT_LE(t.right, right + 0.01f) << "turned by " << yaw;
        }
    }
}

// The view a window opens with (a framed scene camera): beside the open panel, and at a --distance multiple the
// scene's image that many times smaller, its centre still in the free columns' middle.
TEST(AppCamera, TheWindowOpensWithTheSceneBesideThePanel) {
    const Sphere sphere{glm::vec3(-1.0f, 4.0f, 0.5f), 0.8f};
    const float aspect = 1280.0f / 1024.0f;
    const glm::vec2 free(480.0f / 1280.0f, 1.0f);
    const float middle = free.x + free.y - 1.0f;
    float framed_height = 0.0f;
    for (const float multiple : {1.0f, 2.0f, 4.0f}) {
        OrbitCamera camera;
        camera.yaw_deg = 30.0f;
        camera.pitch_deg = 10.0f;
        app::frame_at_open(camera, sphere, aspect, free, multiple);
        EXPECT_FLOAT_EQ(camera.yaw_deg, 30.0f);
        EXPECT_FLOAT_EQ(camera.pitch_deg, 10.0f);
        const CameraMatrices m = camera_matrices(camera, aspect, sphere);
        const glm::vec4 centre = m.proj * m.view * glm::vec4(sphere.center, 1.0f);
        std::printf("x%.1f the framing distance: the centre at x %.3f (the free columns' middle %.3f)\n", double(multiple),
                    double(centre.x / centre.w), double(middle));
        EXPECT_NEAR(centre.x / centre.w, middle, 0.03f);
        EXPECT_NEAR(centre.y / centre.w, 0.0f, 0.01f);
        const Extent e = projected(camera, sphere, aspect);
        if (multiple == 1.0f) {
            framed_height = e.top - e.bottom;
            EXPECT_GE(e.left, 2.0f * free.x - 1.0f - 0.01f) << "under the panel";
            EXPECT_LE(e.right, 1.01f);
        } else {
            EXPECT_NEAR((e.top - e.bottom) / framed_height, 1.0f / multiple, 0.05f / multiple);
        }
    }
}

TEST(AppCamera, TheColumnsAnOpenPanelLeaves) {
    const glm::vec2 window(1280.0f, 1024.0f);
    // Open at the left (the default place), moved to the right, off the window, and over nearly all of it (a
    // narrow window: the whole window then, not a sliver at its edge).
    EXPECT_EQ(app::columns_left_free({10.0f, 10.0f, 470.0f, 990.0f}, window), glm::vec2(480.0f / 1280.0f, 1.0f));
    EXPECT_EQ(app::columns_left_free({900.0f, 0.0f, 380.0f, 700.0f}, window), glm::vec2(0.0f, 900.0f / 1280.0f));
    EXPECT_EQ(app::columns_left_free({1300.0f, 0.0f, 400.0f, 1000.0f}, window), glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(app::columns_left_free({10.0f, 10.0f, 1100.0f, 1000.0f}, window), glm::vec2(0.0f, 1.0f));
}

}  // namespace

namespace {

// The near and far planes hold the whole scene for a camera aimed beside it (a scene file's target and
// world_distance, or after panning): until 2026-12-07 the near plane stood at the straight-line distance to
// the scene's centre less its radius, a depth along the view axis only for a centre on the axis, and cut away
// the front of an object off to the side (a blobby 2.5 units beside a target 5 away lost 2,500 px).
TEST(AppCamera, TheDepthRangeHoldsASceneOffTheViewAxis) {
    std::mt19937 random(11);
    std::normal_distribution<float> normal;
    for (const bool orthographic : {false, true})
        for (const float beside : {0.0f, 1.0f, 2.5f, 3.0f, 4.0f}) {
            const Sphere scene{glm::vec3(beside, -0.5f * beside, 0.0f), 1.0f};
            OrbitCamera camera;
            camera.target = glm::vec3(0.0f);
            camera.distance = 5.0f;
            camera.fov_y_deg = 60.0f;
            camera.yaw_deg = 20.0f;
            camera.orthographic = orthographic;
            const CameraMatrices m = camera_matrices(camera, 1.25f, scene);
            float nearest = 2.0f, farthest = -1.0f;
            for (int i = 0; i < 20000; ++i) {
                const glm::vec3 p =
                    scene.center + scene.radius * glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
                const glm::vec4 clip = m.proj * m.view * glm::vec4(p, 1.0f);
                nearest = std::min(nearest, clip.z / clip.w), farthest = std::max(farthest, clip.z / clip.w);
            }
            EXPECT_GE(nearest, 0.0f) << "clipped by the near plane: " << beside << " beside, ortho " << orthographic;
            EXPECT_LE(farthest, 1.0f) << beside << " beside, ortho " << orthographic;
            // And tight: the sphere's near side is close to the near plane (depth precision).
            EXPECT_LT(nearest, orthographic ? 0.1f : 0.5f) << beside;
        }
}

}  // namespace
