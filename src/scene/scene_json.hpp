#pragma once
// Scene files: JSON, read strictly (an unknown field is an error, so a typo never silently falls
// back to a default) and written back in full (but "paused", written only when true), so a saved scene renders
// the same image.
//
// {
//   "objects": [{"model": "blobby.glb",
//                "transform": {"translate": [x,y,z], "rotate_deg": [x,y,z], "scale": s or [x,y,z]}
//                             or {"matrix": [16 numbers, column-major]},
//                "params": {"dmax": 0.15, "shading_exponent": 1, ...},
//                "ink": [r,g,b] (the object's own ink; default: the scene's)}],
//   "camera": {"yaw": 20, "pitch": 10, "distance": 1.0, "target": [x,y,z], "world_distance": d, "fov_y": 30},
//   "camera_path": [camera, camera, ...],
//   "light": [x,y,z], "paper": [r,g,b], "ink": [r,g,b],
//   "paused": true (the viewer opens it with its animations paused; render ignores it)
// }
//
// Every error is one line: "<file>: <field, e.g. objects[1].params.dmax>: <problem>".
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace stipple {

// Reads and checks a scene file; model paths are resolved against the file's folder and must exist.
Scene load_scene(const std::string& path);

// Parses scene text; `source` names it in messages, `base_dir` resolves relative model paths.
// Does not look at the model files.
Scene parse_scene(const std::string& text, const std::string& source, const std::filesystem::path& base_dir);

// The scene as JSON text; model paths are written relative to `save_dir` where they can be.
std::string scene_to_json(const Scene& scene, const std::filesystem::path& save_dir);

// Writes the scene to `path` (creating folders), with model paths relative to the file's folder.
void save_scene(const std::string& path, const Scene& scene);

// The per-object parameter names a scene file accepts, in the order they are written.
std::vector<std::string> scene_param_names();

}  // namespace stipple
