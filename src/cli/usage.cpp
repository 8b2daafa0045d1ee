#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli/commands.hpp"

namespace stipple::cli {

std::string default_model_path() {
    if (const char* dir = std::getenv("STIPPLE_ASSET_DIR")) return std::string(dir) + "/blobby.glb";
    return std::string(STIPPLE_SOURCE_DIR) + "/assets/blobby.glb";
}

void print_usage() {
    std::printf(R"(stipple - illustrative stipple drawing of polygonal models
(Lu, Taylor, Hartner, Ebert, Hansen: "Hardware-Accelerated Interactive Illustrative
Stipple Drawing of Polygonal Objects", VMV 2002)

Usage:
  stipple render [MODEL] [-o OUT.png] [options]   render one frame offscreen to a PNG
  stipple info MODEL [--json] [options]           load a model, generate its stipples, print figures
  stipple --help                                  this text

MODEL is a .obj, .ply (ASCII or binary, faces or tristrips), .gltf or .glb file. Without MODEL,
render draws the built-in default scene (assets/blobby.glb, a blobby metaball surface made by
tools/make_blobby).

Render options:
  -o, --output PATH       PNG to write (default: stipple.png)
  --mask PATH             also write the coverage mask (white where a surface covers the pixel)
  --width N, --height N   image size in pixels (default 1280 x 1024)
  --yaw DEG, --pitch DEG  orbit the camera around the model (default 0, 0: looking down -Z)
  --distance D            camera distance as a multiple of the framing distance (default 1 = framed)
  --light X,Y,Z           direction toward the light in view space: x right, y up, z toward the
                          viewer (default -0.45,0.55,0.7: upper left, in front)
  --point-size PX         stipple diameter in pixels, 1..64 (default 2; above 2.5 dots are round)
  --stats                 print triangles, candidate and drawn stipples (counted on the GPU), ink
                          coverage, and the GPU time of each pass
  --repeat N              after the image, time N more frames (no read-back) and print the median
                          frame time and GPU time per pass
  --device N              Vulkan device to use (default: the best; --list-devices shows them)
  --list-devices          print the Vulkan devices and exit

Stipple options (render and info):
  --dmax F                D_max, the maximum stipple density in stipples per reference pixel^2
                          (the object framed in a 1024-pixel-high view), 0 < F <= 16 (default 0.2)
  --max-stipples N        Object_max, the object's stipple budget (default 8000000); the density
                          is lowered evenly when D_max would exceed it
  --seed N                seed of the stipple placement (default 1)
  --relax-iterations N    relaxation steps toward a Poisson-disc distribution, 0..100 (default 6)
  --shading-exponent N    n in the shading term (N.L)^n, > 0 (default 1)
  --no-shading            draw every candidate of the front-facing polygons
  --pr F                  extrinsic distance enhancement rate, 0..8 (default 2: stipples per screen
                          pixel stay constant as the object moves away)
  --min-area PX           minimum stipple screen area, 2..9 px^2 (default 4): polygons projecting
                          smaller are drawn by probabilistic selection
  --no-extrinsic          no extrinsic distance enhancement (neither regime)
  --de F                  intrinsic depth enhancement rate, > 0 (default 2; smaller exaggerates)
  --no-intrinsic          no intrinsic depth enhancement
  --density-path P        vertex: compute pass + vertex-shader cull (the paper's vertex program);
                          cpu: CPU densities, only surviving stipples submitted; indirect: compute
                          pass writes compacted draws (vkCmdDrawIndirectCount). Default: vertex
  --silhouette MODE       none, lines (Raskar-Cohen back-face lines), toon (N.E ramp: surfaces
                          darken edge-on, stipples fade there) or both (default none)
  --silhouette-width PX   line width at the object's reference size, 1..64 (default 4)
  --no-thinning           keep the line width fixed instead of thinning it with distance
  --toon-sharpness F      steepness of the toon ramps, 0.5..64 (default 4)

Info options:
  --json                  print the figures as JSON

Environment:
  STIPPLE_VALIDATION=1|0  force the Vulkan validation layer on or off (on in debug builds); any
                          validation message makes the command fail
  STIPPLE_SHADER_DIR      where the compiled shaders (*.spv) are (default: the build folder)
  STIPPLE_ASSET_DIR       where the default scene is (default: the source folder's assets/)

Exit status: 0 on success, 1 on bad input or a failed render (one line on stderr naming the
file and the problem), 2 on a bad command line or Vulkan validation messages.
)");
}

}  // namespace stipple::cli
