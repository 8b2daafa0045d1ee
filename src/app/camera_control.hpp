#pragma once
// Orbit, pan and zoom of the viewer's camera from mouse drags, wheel steps and keys.
// Pure arithmetic on an OrbitCamera, so it can be reasoned about (and tested) without a window.
#include <optional>

#include <glm/glm.hpp>

#include "mesh/mesh.hpp"
#include "render/camera.hpp"

namespace stipple::app {

inline constexpr float kDegreesPerPixel = 0.3f;  // orbit speed of a drag
inline constexpr float kKeyOrbitDegrees = 5.0f;  // one arrow key press
inline constexpr float kZoomPerStep = 0.88f;     // distance factor of one wheel step or +/- press
inline constexpr float kMaxPitch = 89.0f;        // keeps the up vector defined

// Dragging right turns the scene right (the camera moves left around it); dragging down tips it toward the viewer.
void orbit(OrbitCamera& camera, glm::vec2 drag_pixels);
void orbit_degrees(OrbitCamera& camera, float yaw_deg, float pitch_deg);

// The point under the cursor follows it: the target moves in the view plane by the drag in world units
// at the target's depth (viewport_height pixels span the vertical field of view there).
void pan(OrbitCamera& camera, glm::vec2 drag_pixels, float viewport_height);

// Positive steps move closer. The distance stays within [1e-3, 1e3] x the framing distance of `bounds`,
// so the camera can neither pass through the target nor lose the scene.
void zoom(OrbitCamera& camera, float steps, const Sphere& bounds, float aspect);

// Frames `bounds`, keeping the direction, so that it fills the window's columns `free` (fractions of its
// width, from the left: [0, 1] the whole window) and sits in their middle: the viewer leaves out the columns
// its open panel covers. It looks at the centre of `bounds` (the orbit turns about it), and beside the panel
// the image is moved into the free columns by the camera's lens shift.
void frame_all(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free = {0.0f, 1.0f});

// The view a window opens with, its panel open: a framed scene camera (a distance multiple, no target of its
// own) is framed in `free` and then `distance_multiple` times as far, the scene's centre in the free columns'
// middle (the window opened with a third of the scene under the panel); a placed camera (none: a target or a
// world distance, as Ctrl+S saves) keeps its view, its target moved into the free columns' middle.
void frame_at_open(OrbitCamera& camera, const Sphere& bounds, float aspect, glm::vec2 free,
                   std::optional<float> distance_multiple);

// The lens shift (OrbitCamera::lens_shift) that puts the view's middle in the middle of the columns `free`.
float lens_shift_into(glm::vec2 free, float aspect);

// The wider run of the window's columns left and right of `rect` (the open panel's x, y, width, height in
// pixels), as fractions of `window` (its width and height in those pixels); the whole window where the
// panel covers none of it, or where what it leaves is under a quarter of the width (a narrow window).
glm::vec2 columns_left_free(glm::vec4 rect, glm::vec2 window);

// The camera's right and up axes in world space.
glm::vec3 camera_right(const OrbitCamera& camera);
glm::vec3 camera_up(const OrbitCamera& camera);

}  // namespace stipple::app
