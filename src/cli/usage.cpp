#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "params/param_docs.hpp"

namespace stipple::cli {

std::string default_model_path() {
    if (const char* dir = std::getenv("STIPPLE_ASSET_DIR")) return std::string(dir) + "/blobby.glb";
    return std::string(STIPPLE_SOURCE_DIR) + "/assets/blobby.glb";
}

namespace {

void header() {
    std::printf(R"(stipple - illustrative stipple drawing of polygonal models
(Lu, Taylor, Hartner, Ebert, Hansen: "Hardware-Accelerated Interactive Illustrative
Stipple Drawing of Polygonal Objects", VMV 2002)

)");
}

void model_section() {
    std::printf(R"(MODEL is a .obj, .ply (ASCII or binary, faces or tristrips), .gltf or .glb file (glTF quantized,
compressed or instanced too: KHR_mesh_quantization, EXT_meshopt_compression, KHR_draco_mesh_compression,
EXT_mesh_gpu_instancing), or a .stl file (binary or ASCII, as CAD and 3D-printing tools write). Without
MODEL or scene, render and view draw the built-in default scene (assets/blobby.glb, a blobby metaball
surface made by tools/make_blobby). Several MODELs given to view are set side by side, each scaled to the
first one's size. The stipple options below apply to MODELs; a SCENE.json sets them per object
(combining the two is an error).

)");
}

void render_section() {
    std::printf(R"(Render options:
  -o, --output PATH       PNG to write (default: stipple.png; missing folders are made)
  --mask PATH.png         also write the coverage mask (white where a surface covers the pixel)
  --width N, --height N   image size in pixels (default 1280 x 1024)
  --stats                 print triangles, candidate and drawn stipples (counted on the GPU), the
                          mean ink inside the object (as tone measures it), and the GPU time of each pass
  --repeat N              after the image, time N more frames (no read-back; 0..100000) and print
                          the median frame time and GPU time per pass, and the least
  --queued K              with --repeat: each timed frame is K frames queued back to back in one
                          submission, over K (1..1000; default: 1 on a CPU device, 8 on a GPU, as
                          for bench)
  --depth-cull MODE        auto, on or off: the depth pass draws only the triangles that may cover a
                          pixel centre, listed by a compute pass (the same image). auto considers it
                          for models whose triangles average under 2 px on screen and keeps it where
                          the frames' GPU times show that it pays (default auto)
  --depth-raster MODE     auto, compute or fixed: the depth pass as a compute pass over the triangles,
                          spread over every core, or the fixed-function pass. auto: compute on a CPU
                          device (lavapipe) while triangles average under 24 px on screen or the
                          models' facing surface is under 0.6 of the frame, else fixed, and fixed
                          for an object on the vertex, indirect or cpu path; a frame with a toon
                          object is always fixed, compute asked or not (--stats says so) (default
                          auto)
  --device N              Vulkan device to use (default: the best; --list-devices shows them)
  --list-devices          print the Vulkan devices and exit
  --verbose               print the device chosen
  --frames N              render N frames: an orbit (--orbit) or the scene's camera_path sampled at
                          N evenly spaced points (a camera_path alone gives one frame per keyframe)
  --orbit DEG             turn the camera by DEG in total around the scene's centre, DEG*i/N at
                          frame i (so 360 loops without a repeated frame); needs --frames
  --animation NAME|N      what an animated glTF MODEL plays: an animation's name or index (default:
                          its first); `stipple info MODEL` lists them
  --time SECONDS          the scene clock of the (first) frame (default 0); animations loop
  --fps F                 an animated model's frames per second in a sequence (--frames N or a
                          camera_path; 0.001..1000, default 30): frame i shows --time + i/F; --frames
                          alone renders the animation (a still model's sequence takes no --fps)

)");
}

void camera_section() {
    std::printf(R"(Camera, light and colours (render and view):
  --yaw DEG, --pitch DEG  orbit the camera around the model (default 0, 0: looking down -Z; yaw
                          within +-36000, pitch within +-90)
  --distance D            camera distance as a multiple of the framing distance (default 1 = framed;
                          0.0001..10000)
  --light X,Y,Z           direction toward the light in view space: x right, y up, z toward the
                          viewer (default -0.45,0.55,0.7: upper left, in front)
  --orthographic          parallel lines of sight (technical and scientific illustration) instead of
                          perspective: the view spans at every depth what it spans at the target, so
                          --distance sets the scale; the tone rules read the same (§2.3's distance is
                          the scale on screen). A scene camera's "projection": "orthographic"
  --perspective           perspective, for a scene file whose camera is orthographic
  --ink COLOUR, --paper COLOUR
                          the colours of the stipples and lines, and of the paper: #rrggbb (#rgb)
                          or R,G,B each in 0..1 (default #000000 on #ffffff); a scene file's
                          objects may each have their own ink ("ink" below)

)");
}

void vector_section() {
    std::printf(R"(Vector and print output (render):
  -o x.svg | x.pdf | x.csv
                          the stipples the frame draws (after density, hidden-stipple removal, toon
                          fade; not a toon object's edge-on grey, a fill on screen) as dots, and its
                          visible lines, on a page in mm, ordered for pen
                          plotters; layers per object and kind (an SVG's Inkscape layers, a PDF's
                          groups: docs/plot-export.md); the image-space --silhouette-lines become the
                          outline they trace (the contours). x.csv holds the dots alone, one row each
  --page SIZE             A3, A4, A5, letter, legal or WxHmm, optionally -portrait or -landscape
                          (WxHmm: 10 mm to 10 m a side, a PDF's at most 5080 mm; default A4 for
                          vector output; a print image names its page). A named size without
                          -portrait or -landscape is turned as the drawing is (landscape when wider
                          than tall); with --fit frame and no --width a print image's is portrait
  --margin MM             border of bare paper around the drawing (0..500, default 10)
  --fit WHAT              vector output and print images: drawing (what is drawn, its dots and
                          lines, fills the page inside the margins, enlarged at most 4 times) or
                          frame (the whole frame, empty paper included, as the screen shows it)
                          (default: drawing; frame for a frame sequence, so that its pages line up)
  --pen-width MM          stroke of lines and of circle/tick dots (above 0, at most 10; default:
                          lines as wide as drawn, dots 0.3)
  --dot-style STYLE       filled (discs, for print and PDF; default), circle or tick (for plotters)
  --fill-paper            SVG and PDF: paint the page in the scene's paper colour (a print image's
                          page is always the paper colour)
  --show-travel           SVG: draw the pen-up moves in light red, to look at the plot order (in a
                          layer named "%% ...", which the AxiDraw software does not plot)
  --dpi N                 with -o x.png and --page: a print-resolution page (50..2400 dpi) that looks
                          like the screen image enlarged: the same stipples, each a disc of the same
                          share of ink, as at --height pixels (default 1024) for the drawing's height;
                          its size follows the page, its dpi is in the PNG. The screen frame it enlarges
                          takes the page's shape, or with --width the screen image's (--width W
                          --height H prints the composition of the W x H screen image)
  --tile N                print images are drawn in tiles of at most N pixels a side (64..16384,
                          default 4096)

  With several frames, -o (and --mask) must hold a frame number, %%d or %%0Nd: -o frames/%%04d.png
  writes frames/0000.png, frames/0001.png, ... (%%%% is a literal %%, in a single frame's -o too). A
  progress bar shows on a terminal; the same command always writes the same files (but a PDF's creation
  date, unless SOURCE_DATE_EPOCH gives it). With a SCENE.json, --yaw, --pitch, --distance,
  --orthographic or --perspective, --light, --ink and --paper override the scene's camera, light and
  colours (an object's own "ink" stays its own; the projection asked draws a camera_path's frames too,
  and --yaw, --pitch and --distance are refused with one: the path sets the camera).

)");
}

void view_section() {
    std::printf(R"(View options (and the camera, light and colours, and the stipple options):
  --width N, --height N   window size (default 1280 x 1024)
  --device N              Vulkan device to use (default: the best; stipple render --list-devices
                          shows them)
  --no-vsync              present without waiting for the display (MAILBOX or IMMEDIATE) from the start
  --present MODE          auto, swapchain or shm: how frames reach the window. shm hands them to the
                          X server through shared memory (MIT-SHM), where lavapipe's swapchain writes
                          each frame into the X socket when the server lacks DRI3 (Xvfb, Xvnc);
                          vsync then holds frames to the monitor's refresh rate. auto: shm on a CPU
                          device where the server allows it, else swapchain (default auto)
  --no-panel              start with the panel hidden
  --no-count-drawn        do not count drawn stipples on the GPU (saves an atomic per stipple)
  --depth-cull MODE       auto, on or off, as for render (stipple render --help; default auto)
  --depth-raster MODE     auto, compute or fixed, as for render (default auto)
  --screenshot-dir DIR    where S writes screenshots, stipple-0001.png, ... (default: .)
  --save-scene PATH.json  where Ctrl+S writes the scene (default: the scene file it opened, else
                          stipple-scene.json); checked when the viewer starts
  --benchmark-frames N    draw 10 warm-up frames, then N frames, print the mean fps and exit
  --animation NAME|N      what the animated glTF MODELs play (beside static ones): an animation's
                          name or index (default: each one's first); `stipple info MODEL` lists them
  --time SECONDS          the scene clock at the start (default 0); animations loop
  --verbose               print the device and every swapchain (re)creation
  --script FILE           timed actions, one per line: wait SECONDS, wait-idle (until new stipples
                          or dropped models are shown), set OBJECT KEY VALUE (a parameter by its
                          scene key), screenshot PATH (.png), export PATH (.svg, .pdf or .csv, as
                          render -o writes them), quit; a bad line, or a setting the scene
                          refuses, ends the run with exit code 1, naming the file and line; a
                          script without quit leaves the window open for a person when it ends
  --frame-log FILE        write one line per presented frame: milliseconds since the start
                          and 1 while background work (new stipples, a model) runs, else 0

  Mouse: left drag orbits, right or middle drag pans, the wheel zooms. Drop model files onto the
  window to add them beside the others. Keys: arrows orbit, + and - zoom, F frames everything
  (beside the open panel, as the window opens: --distance is then a multiple of that framing),
  H hides/shows the panel (folded to its title in a window under 1000 px wide: click to open it),
  S saves a screenshot (window resolution, without the panel), V toggles vsync, O switches between
  perspective and orthographic projection, Space plays or
  pauses the animation, Ctrl+S saves the scene, Escape or Q quits (Escape first closes an open
  list). The panel sets every per-object parameter (generation parameters take effect on release or Enter: new
  stipples are made in the background with a progress bar while the old ones are drawn, and a newer
  value cancels an older one; dropped models load in the background too), the light, paper and ink
  colours, and shows at its top fps, CPU and GPU frame time and stipple counts, and at its foot the
  GPU time of each pass (the panel's own included), refreshed twice a second, times averaged over the
  half second. With an animated
  model a timeline window plays, pauses and scrubs the animation, sets its speed and loop, and
  chooses each object's animation. The window is drawn on demand: while an animation plays, a script
  or --benchmark-frames runs, and for a second after any input; otherwise the viewer sleeps (ten
  frames a second while new stipples are made, for the progress bar).

)");
}

void scene_section() {
    std::printf(R"(Scene files (JSON; model paths relative to the file; unknown fields are errors):
  {"objects": [{"model": "blobby.glb",
                "transform": {"translate": [x,y,z], "rotate_deg": [x,y,z], "scale": s or [x,y,z]}
                             (or {"matrix": [16 numbers, column-major]}; a negative axis scale,
                             [-1, 1, 1], or a matrix of negative determinant draws the mirror image;
                             an animated model cannot be mirrored: mirror it in its file),
)");
    // The parameters come from the one table (src/params/param_table.cpp): never retyped here.
    std::istringstream example(param_scene_example());
    for (std::string line; std::getline(example, line);) std::printf("                %s\n", line.c_str());
    std::printf(R"(                (an animated glTF model also: "animation": {"name": "Walk" or an index (default:
                 its first), "start": seconds into it at time 0, "speed": 1, "loop": true}),
                "ink": [r,g,b] (the object's own ink: its stipples, lines and toon shade, and its
                               layers in vector output; default: the scene's ink)
   }],
   "camera": {"yaw": 0, "pitch": 0, "distance": 1 (x the framing distance) or "world_distance": d,
              "target": [x,y,z] (default: the centre of the scene), "fov_y": 30,
              "projection": "perspective" or "orthographic"},
   "camera_path": [camera, camera, ...],
   "light": [x,y,z], "paper": [r,g,b], "ink": [r,g,b],
   "paused": false (true: the viewer opens it with its animations paused, as Ctrl+S saves a paused
             timeline; render ignores it)}
  Every field is optional except objects and their model (params above at their defaults). A param
  takes the range of its stipple option below; `stipple params --markdown` pairs each scene key with
  its option.
)");
}

void stipple_section() {
    std::printf("Stipple options (render, view, info, tone and parity; a SCENE.json sets them per object instead):\n");
    std::fputs(param_help_text().c_str(), stdout);
    std::printf("\n");
}

void info_section() {
    std::printf(R"(Info options:
  --json                  print the figures as JSON
  An animated glTF model also lists its animations (durations, channels), skins (joints) and morph
  targets, and its stretch headroom: the largest area any polygon reaches and the candidates that buys.

)");
}

void cache_section() {
    std::printf(R"(Stipple cache options (render, view, info, tone, parity, cache): generated stipples are kept on
disk, so a model reopened with the same generation parameters skips generation (~4-5 bytes per
stipple, checked when read; a damaged entry is reported and regenerated)
  --cache-dir DIR         where (default: $STIPPLE_CACHE_DIR/stipples, else
                          $XDG_CACHE_HOME/stipple/stipples, else ~/.cache/stipple/stipples; an
                          empty variable counts as unset, and a relative XDG_CACHE_HOME too (a
                          relative STIPPLE_CACHE_DIR is taken from the current folder); without a
                          home a private stipple-cache-UID/stipples in the temporary folder)
  --cache-size SIZE       the folder's limit, e.g. 500M or 2G (M and G: MiB and GiB; default 1G);
                          when an entry is written, the least recently used ones are removed beyond
                          it (an entry larger than the whole limit is not kept)

)");
}

void tone_section() {
    std::printf(R"(Tone options (and the stipple options but --extrinsic and --no-extrinsic, which tone turns on and off
itself; without MODEL the default scene's model):
  --distances 1,2,4,8,16  camera distances, multiples of the framing distance
  --views 30:10,...       YAW:PITCH pairs in degrees (default 30:10), one table row each
  --frames N              average each view over N frames at yaws spread over --arc DEG (1..64,
                          default 1; the arc defaults to 40 with frames; 360 goes all around the
                          object)
  --fov DEG               vertical field of view (default 30); a narrow one keeps the same surface in
                          view at every distance (perspective shows a framed object's sides less)
  --orthographic          parallel lines of sight: the same surface in view at every distance, only
                          its scale changing (the distances then set the scale as render's does)
  --width N --height N    image size (default 1280 x 1024)  --light X,Y,Z  --device N
  --regimes               also print, per distance, the stipples each regime of the extrinsic
                          enhancement owes and draws, and the ink they leave on the screen
  --seeds 1,2,3           one table per seed (the stipples and the selection generated again), then
                          each distance's ink averaged over the seeds (instead of --seed)
  --images DIR            write each view and distance (cropped to the object; a crop of 128 px or
                          less enlarged by a whole factor, at most 8, to 129-256 px) as PNG:
                          DIR/tone-YAW_PITCH-dDISTANCE-on.png (and -off), named by the view; with
                          --frames the first frame's, at the start of the --arc
  A distance at which the object covers no pixel or inks none (beyond the frame, the camera inside it,
  thinner than a pixel, or only the back of a one-sided surface in view) shows as - and is left out of
  max/min, with a warning. A distance or seed given twice is refused.
  Where a view's figure rests on so few dots that sampling alone may move it by over 2.5%% (1/sqrt
  of the dots), a last line says so, with the dots and the spread.

)");
}

void parity_section() {
    std::printf(R"(Parity options (and the stipple options but --density-path, which --paths replaces; without MODEL the
default scene's model; exit status 1 when the drawn counts differ by more than 0.1%% or the mean ink by
more than 1%% in any view):
  --devices I,J           the two devices (default 0,1; stipple render --list-devices shows them;
                          0,0 compares a device with itself)
  --paths splat,vertex    the density paths to compare (default splat,vertex)
  --yaws N                views all around the model at two elevations (default 8)
  --width N --height N    image size (default 1280 x 1024)

)");
}

void bench_section() {
    std::printf(R"(Bench options (one model per Table 1 row, derived from ../shared/models, else UV spheres):
  --quick                 horse and low-res dragon, vertex, cpu and splat paths, 5 timed frames, only
                          the paper's columns (without the contours, borders and creases columns)
  --out DIR               where results.md, results.json, chart.svg, images/ go (default: bench-results)
  --models a,b  --paths vertex,cpu,...|all  --frames N (default 20)  --warmup N (default 3)
                          (rows: horse, low-res-dragon, bunny, skeleton1, skeleton2, hand, dragon)
  --width N --height N (default 1280 x 1024)  --device N  --list-devices
  --models-dir DIR        where the scans are (default: $STIPPLE_SHARED_MODELS, else the source
                          folder's ../shared/models); a row whose scan is not there is a UV sphere of
                          its polygon count (a folder named here must exist)
  --cache-dir DIR         where the models derived from them are kept (not the stipple cache;
                          default: $STIPPLE_CACHE_DIR/bench-models, else the build folder's bench-models)
  --animated-triangles N  the animated row's skinned cylinder (default 100000, --quick 20000; 0: none;
                          not run when --models names rows, unless this is given)
  --animated-only         the animated row alone (no --models or --paths with it)
  --depth-cull MODE       auto, on or off, as for render (default auto)
  --depth-raster MODE     auto, compute or fixed, as for render (default auto)
  --queued N              queue N frames back to back per submission, each timed frame the batch's wall
                          time over N (default: 1 on a CPU device such as lavapipe, 8 on a GPU, which
                          waited on after every small frame idles and lowers its clocks)
  --compare OLD.json      after the run, list the cells (fps, generation, plot order) more than 10%%
                          slower than in an earlier results.json, and those only one of the two has
  --plot-dots N           the plot-order row's blue-noise dots (default 150000, --quick 15000 without
                          the bunny's view; 0: no row; with --models only when given)

)");
}

void environment_section() {
    std::printf(R"(Environment:
  STIPPLE_VALIDATION=1|0  force the Vulkan validation layer on or off (on in debug builds); any
                          validation message makes the command fail
  STIPPLE_SHADER_DIR      where the compiled shaders (*.spv) are (default: the build folder)
  STIPPLE_ASSET_DIR       where the default scene is (default: the source folder's assets/)
  STIPPLE_SHARED_MODELS   where bench finds the scans (default: the source folder's ../shared/models)
  STIPPLE_CACHE_DIR       bench's derived models go to $STIPPLE_CACHE_DIR/bench-models (default:
                          the build folder's bench-models); the stipple cache is
                          $STIPPLE_CACHE_DIR/stipples (render, view, info, tone and parity: see --cache-dir)
  STIPPLE_NO_CACHE=1      always generate the stipples (neither read nor write the stipple cache)
  STIPPLE_THREADS=N       threads for generation and the CPU passes (default: the hardware's; 1: serial)
  STIPPLE_GPU_MEMORY_LIMIT=SIZE  act as if the device had at most SIZE (e.g. 64M) of memory: how a
                          smaller GPU refuses an object or scene too big for it, tried on a big one
  STIPPLE_GPU_ALLOCATION_LIMIT=N  act as if the device allowed at most N memory allocations at once
                          (Windows drivers allow 4096): how a crowd of objects is refused there
  STIPPLE_HOST_MEMORY_LIMIT=SIZE  act as if this machine had at most SIZE (e.g. 2G) of memory (it
                          also reads a control group's limit): how a smaller machine refuses a model
                          file or stipples it could not hold
  STIPPLE_MAX_STORAGE_BUFFER=SIZE  act as if the device's largest storage buffer were SIZE: render
                          draws an image whose pixel words do not fit one in tiles (lavapipe: 128M)
  STIPPLE_MAX_WORKGROUPS=N  act as if a compute dispatch could have at most N workgroups along x: how
                          a model of millions of polygons is dispatched (in rows; lavapipe: 65535)

)");
}

void exit_section(bool one_command) {
    std::printf(R"(Exit status: 0 on success, 1 on bad input, a bad option or a failed render (one line on stderr
naming the file or option and the problem), 2 on an unknown command or Vulkan validation messages.
)");
    std::printf(one_command ? "`stipple --help` lists every command and all their options.\n"
                            : "`stipple COMMAND --help` prints what that command takes.\n");
}

struct CommandHelp {
    const char* name;
    const char* entry;  // its lines of the command list
    std::array<void (*)(), 8> sections;  // in order; the unused ones null
};

constexpr CommandHelp kCommands[] = {
    {"render",
     R"(  stipple render [MODEL | SCENE.json] [-o OUT.png] [options]
                                  render one frame (or a numbered frame sequence) offscreen to PNG
)",
     {&model_section, &render_section, &camera_section, &vector_section, &scene_section, &stipple_section, &cache_section, &environment_section}},
    {"view",
     R"(  stipple view [SCENE.json | MODEL ...] [options]
                                  open a window: turn, move and tune the drawing interactively
)",
     {&model_section, &view_section, &camera_section, &scene_section, &stipple_section, &cache_section, &environment_section}},
    {"info",
     R"(  stipple info MODEL [--json] [options]
                                  load a model, generate its stipples, print figures
)",
     {&model_section, &info_section, &stipple_section, &cache_section, &environment_section}},
    {"bench",
     R"(  stipple bench [--quick] [options]
                                  the paper's Table 1 on this machine: results.md, .json, chart.svg
)",
     {&bench_section, &environment_section}},
    {"tone",
     R"(  stipple tone [MODEL] [options]  does the model keep its tone as it moves away (§2.3)? mean ink
                                  inside its footprint per distance, extrinsic enhancement on and off
)",
     {&model_section, &tone_section, &stipple_section, &cache_section, &environment_section}},
    {"parity",
     R"(  stipple parity [MODEL] [options]
                                  do two Vulkan devices (lavapipe and a GPU) draw the same stipples?
)",
     {&model_section, &parity_section, &stipple_section, &cache_section, &environment_section}},
    {"params",
     R"(  stipple params [--markdown]     list the per-object parameters: options, ranges, defaults (with
                                  --markdown the README's table, with each one's scene key)
)",
     {}},
    {"cache",
     R"(  stipple cache --list | --clear  what the stipple cache holds, or empty it
)",
     {&cache_section, &environment_section}},
};

void command_list() {
    std::printf("Usage:\n");
    for (const CommandHelp& command : kCommands) std::fputs(command.entry, stdout);
    std::printf("  stipple --help                  this text (stipple COMMAND --help or stipple help COMMAND: one\n"
                "                                  command's options)\n"
                "  stipple --version               the version\n\n");
}

}  // namespace

void print_usage() {
    header();
    command_list();
    model_section();
    render_section();
    camera_section();
    vector_section();
    view_section();
    scene_section();
    stipple_section();
    info_section();
    cache_section();
    tone_section();
    parity_section();
    bench_section();
    environment_section();
    exit_section(false);
}

bool print_command_usage(const std::string& name) {
    for (const CommandHelp& command : kCommands) {
        if (name != command.name) continue;
        header();
        std::printf("Usage:\n");
        std::fputs(command.entry, stdout);
        std::printf("\n");
        for (void (*section)() : command.sections)
            if (section) section();
        exit_section(true);
        return true;
    }
    return false;
}

}  // namespace stipple::cli
