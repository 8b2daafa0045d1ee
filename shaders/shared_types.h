// Struct layouts, limits and workgroup sizes shared by C++ and GLSL: one definition, read by both.
// C++ includes it through src/gpu/shared_types.hpp, which static_asserts every size and offset.
// Only vec4/mat4/scalar members (or vec3 followed by a scalar), so std140/std430 and C++ agree.
#ifndef STIPPLE_SHARED_TYPES_H
#define STIPPLE_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace stipple::gpu {
using glm::mat4;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = uint32_t;
#define STIPPLE_CONST inline constexpr
#else
#define STIPPLE_CONST const
#endif

STIPPLE_CONST uint kDensityWorkgroupSize = 64;
// Every compute pipeline's specialisation constant for the widest dispatch row (shaders/dispatch.h); an id
// no shader uses for anything else.
STIPPLE_CONST uint kSpecMaxGroupsX = 31;

// The splat's work items: a polygon's drawn stipples in runs of at most this many, one invocation each.
// lavapipe (gallivm) stops every loop of an invocation once it has run LP_MAX_TGSI_LOOP_ITERATIONS
// (65535) iterations in all, silently: one invocation walking a large polygon's 10,000 stipples with
// their pixel loops inked only the first ~3,500 (a framed 12-triangle cube read 0.08 instead of 0.27
// ink). A run of 64 stipples costs ~6 iterations each (one-pixel to two-pixel dots), ~60 for 4x dots:
// far under the limit.
STIPPLE_CONST uint kSplatChunk = 64;
// A polygon drawing at most kSplatChunk stipples is cut into runs of this many instead
// (splat_run_length): the invocations of a SIMD vector wait for the longest run among them, and a
// polygon's few to few dozen stipples vary from one polygon to the next. On the low-res dragon (45k
// polygons, ~3 drawn each, up to a few dozen) the splat took 4.45 ms against 5.33 with runs of 64
// (median of 4 alternating runs each; the density pass, where more polygons then claimed several items
// with an atomic add each, 1.06 to 1.18 ms, until the subgroup's items were claimed at once); 8 gave
// 4.72 and 16 4.85. The bunny, the horse and the ogre,
// whose polygons draw 1-3, did not change. Polygons that draw more keep runs of kSplatChunk: a framed
// 12-triangle cube, all runs full, was 20% slower with runs of 4 (each run reads its polygon again).
STIPPLE_CONST uint kSplatShortRun = 4;
// Large dots cost more iterations: a dot walks its box of pixel centres, and a dot astride the outline
// searches a ring around that box for each pixel it moves inward (splat.comp). Runs of 64 dots of 16 px
// (289 box iterations each) went past the limit: on a framed cube with 16-px dots at D_max 0.004 the
// splat drew 981 stipples where the points pipeline drew 1,189 (32-px dots: 127 against 596). So the
// splat's runs are shortened to keep each invocation within kSplatIterationBudget (splat_run_length), a
// dot moves no more pixels than kSplatRingFactor times its box's iterations allow (at most kSplatRingCap
// iterations of ring search; 1.5- to 6-px dots never reach it), and its side is at most kSplatMaxSide
// pixels, so that even kSplatShortRun of the largest dots fit: the points pipeline's largest are 256
// (64-px points at kMaxStippleScale).
// The depth pass's slope-scaled polygon offset (vkCmdSetDepthBias's slope factor; the constant is in
// stipple_renderer.hpp): a surface is pushed back by this many times its depth change per pixel, which
// leaves one- to two-pixel dots on their own surface (large_dot_depth_pull does the rest for larger ones).
STIPPLE_CONST float kDepthBiasSlopeFactor = 1.5f;
// Its constant factor, in units of the depth format's resolution (also vkCmdSetDepthBias's).
STIPPLE_CONST float kDepthBiasConstant = 2.0f;
// The faces facing away of an open one-sided object are in the depth pass only to hide what lies behind
// them through its holes; they carry no stipples. Pushed back this many times further (both factors), they
// lose the ties along the outline where the offset put them before the front faces beside them (which cut
// the bunny's toon outline and hid stipples there).
STIPPLE_CONST float kBackFaceBiasScale = 4.0f;
STIPPLE_CONST uint kSplatIterationBudget = 32768;
STIPPLE_CONST uint kSplatRingFactor = 32;
STIPPLE_CONST uint kSplatRingCap = 2048;
STIPPLE_CONST float kSplatMaxSide = 100.0f;
// Stipples of this size in pixels and below are square points; above, round dots (draws_round_points), and
// square ones enlarged beyond it become discs (enlarged_square_extent).
STIPPLE_CONST float kRoundPointsAbovePx = 2.5f;

// Specialisation constants (variants without copied shader files).
STIPPLE_CONST uint kSpecCountDrawn = 0;      // stipple.vert, splat.comp: record drawn stipples in the debug buffer
STIPPLE_CONST uint kSpecDrawnList = 1;       // stipple.vert: draw the survivors' list (DrawnStipples), not every candidate
STIPPLE_CONST uint kSpecListDrawn = 0;       // density.comp: append polygons with stipples to the splat's list
STIPPLE_CONST uint kSpecDepthUnorm24 = 9;    // scene_depth.h (splat.comp, stipple.vert), line_walk.comp, silhouette_words.frag, depth_raster.comp, depth_coverage.comp: the depth words are X8_D24 (else float bits)
STIPPLE_CONST uint kSpecRecordVisible = 2;   // splat.comp: list every drawn stipple that inks a pixel (export)
STIPPLE_CONST uint kSpecMeshVec3Texels = 3;  // stipple_position.h: a vertex (triangle) per mesh texel, else a float (index)
// silhouette.frag, silhouette_words.frag: the Raskar-Cohen lines' round caps, points of the line's width at an end
// of each edge (silhouette_caps.vert; wide lines are rectangles: over a fine mesh's short edges at 16-64 px they
// left cracks and a comb-like outer edge); drawn where the lines are wider than kLineCapsAbovePx. Each costs about
// the width squared in pixels, hidden ones too (docs/paper-reading.md): below 12 px the cracks hardly show and the
// caps would double the line pass of a fine mesh.
STIPPLE_CONST uint kSpecLineCaps = 8;
STIPPLE_CONST float kLineCapsAbovePx = 12.0f;
// splat.comp: round dots (kFlagRoundPoints), and print detail's whole dots (FrameView::detail_scale > 1).
// Variants, not runtime flags: lavapipe runs both sides of a branch under a mask, so the code of a
// feature that is off still cost every stipple (the bunny's splat 4.6-5.2 ms with them as flags,
// 3.9-4.9 without).
STIPPLE_CONST uint kSpecRoundPoints = 4;
STIPPLE_CONST uint kSpecWholeDot = 5;
// splat.comp: which list a dispatch walks (kSplatList*) and whether it has the code of the density across a
// polygon (stipple_density_here). For the same reason as above, two pieces of its code that few dots need
// are kept out of the dispatch that draws most of them:
// - the density across polygons large on screen (least < most): with GPU densities the gradient pass lists
//   their work items apart (kSplatListVarying, in kBindingDrawnStipples) and a second dispatch draws them;
// - the outline ring (a dot astride the object's outline inks its lost pixels on the visible ones nearest
//   it): a dispatch lists the work items with such a dot (kBindingSplatRing) and the ring dispatch inks
//   those pixels alone.
// Every pixel is inked by an order-independent atomic or the least word, so the image is the one pass's.
// (On the 871k-triangle bench dragon the two took the splat from 14.5 to 10.2 ms in a one-pass ablation.)
STIPPLE_CONST uint kSpecSplatList = 6;
STIPPLE_CONST uint kSpecVaryingDensity = 7;
STIPPLE_CONST uint kSplatListDrawn = 0;    // the work list (kBindingDrawnPolygons)
STIPPLE_CONST uint kSplatListVarying = 1;  // the work items of the polygons whose density varies (GPU densities)
STIPPLE_CONST uint kSplatListRing = 2;     // the work items with a dot astride the outline: the ring pass
// stipple.vert, vertex path: the draw of every candidate culls those of the polygons whose density changes
// across them (draw.least < draw.most, stipple_density_here), and a second, instanced draw takes them in
// chunks of kGradientChunk candidates (GradientChunks), one instance a chunk. lavapipe runs the code of a
// branch for every lane, taken or not: the density across a polygon (its corners and terms) cost every
// candidate, about a third of the pass, where a few hundred polygons need it.
STIPPLE_CONST uint kSpecGradientListed = 5;  // the draw of every candidate, without that code
STIPPLE_CONST uint kSpecGradientChunks = 6;  // the second draw
STIPPLE_CONST uint kGradientChunk = 8;
// stipple.vert: the variant that moves dots astride the outline onto the surface (outline_shift), for objects
// small on screen (kOutlineShiftBelowPx, src/render/object_gpu.hpp); a variant, not a flag, for the same reason
STIPPLE_CONST uint kSpecOutlineShift = 7;
STIPPLE_CONST uint kSpecFacingOnly = 1;      // density.comp: only the facing bits (the CPU density paths' objects with lines)
// density.comp: the variant that writes the facing bits (objects with lines); the others skip its ballot.
STIPPLE_CONST uint kSpecFacingBits = 2;
// density.comp: the gradient pass, over the polygons the density pass listed as large on screen
// (kBindingGradientPolygons): the bounds of the density across each, and their work items.
STIPPLE_CONST uint kSpecGradientPass = 4;
// density.comp, the gradient pass for the vertex path: lists the chunks of the polygons whose density
// changes across them (GradientChunks in kBindingDrawnStipples), which its draw of every candidate leaves out.
STIPPLE_CONST uint kSpecListGradientChunks = 5;
// density.comp, the gradient pass for the splat with GPU densities: lists the work items of the polygons
// whose density varies across them in kBindingDrawnStipples (a DrawnPolygons list) rather than the work list.
STIPPLE_CONST uint kSpecListVaryingApart = 6;

// Descriptor bindings of the one set every stipple pipeline uses (set 0).
STIPPLE_CONST uint kBindingFrame = 0;          // FrameUniforms (uniform)
STIPPLE_CONST uint kBindingObject = 1;         // ObjectUniforms (uniform)
STIPPLE_CONST uint kBindingTriangleDraw = 2;   // TriangleDraw[] (storage), per frame
STIPPLE_CONST uint kBindingTriangleInfo = 3;   // TriangleInfo[] (storage), constant
STIPPLE_CONST uint kBindingDrawnStipples = 4;  // DrawCommand + uint[] (storage): the survivors' list (indirect, cpu);
                                               // the splat with GPU densities: its varying polygons' work items
STIPPLE_CONST uint kBindingDebug = 5;          // DebugCounters (storage): drawn count + drawn bit mask
// DrawnPolygons header + uint[] (storage): the splat's work items with a dot astride the outline
// (kSplatListRing), at most one per work item.
STIPPLE_CONST uint kBindingSplatRing = 6;
STIPPLE_CONST uint kBindingDrawnPolygons = 7;  // DrawnPolygons header + uint[] (storage): the splat's work list (the indirect path lists from it too)
STIPPLE_CONST uint kBindingMeshPositions = 8;  // texel buffer: the mesh's vertices (RGB32F, or R32F: kSpecMeshVec3Texels)
STIPPLE_CONST uint kBindingMeshIndices = 9;    // texel buffer: the mesh's triangles (RGB32UI, or R32UI)
// texel buffer (RGBA32UI): SilhouetteEdge[], every edge of the mesh once, an edge per texel (the line
// passes: one gather instead of four lane-by-lane loads)
STIPPLE_CONST uint kBindingSilhouetteEdges = 10;
STIPPLE_CONST uint kBindingSilhouetteLines = 11;  // SilhouetteLines header + uint[] (storage): this frame's lines
STIPPLE_CONST uint kBindingVisibleStipples = 12;  // VisibleStipplesHeader + VisibleStipple[] (storage), when recording
STIPPLE_CONST uint kBindingFacing = 13;           // uint[] (storage): one bit per polygon, set when it faces away (cleared, then or-ed)
STIPPLE_CONST uint kBindingLinePieces = 14;       // LinePiecesHeader + LinePiece[] (storage): visible object-space lines
STIPPLE_CONST uint kBindingLineCandidates = 15;   // LineCandidates + uint[] (storage): the edges to walk this frame
// float[] (storage), per polygon, constant: the object-space area at which all of its candidates are due
// (its rest area times its stretch headroom, src/anim/headroom.hpp). Read with kFlagStretch only.
STIPPLE_CONST uint kBindingFullAreas = 16;
// texel buffer (RGBA32UI): the TriangleDraw[] of kBindingTriangleDraw, a polygon per texel, for the shaders
// that read it at scattered places (stipple.vert, splat.comp: one gather instead of a load per member).
STIPPLE_CONST uint kBindingTriangleDrawTexels = 17;
// texel buffer (RGBA32UI): the TriangleInfo[] of kBindingTriangleInfo, a polygon per texel (density.comp:
// one gather instead of four lane-by-lane loads).
STIPPLE_CONST uint kBindingTriangleInfoTexels = 18;
// DepthTriangles header + uint[] (storage, also the index and indirect buffer of the depth pass): the
// triangles that can cover a pixel centre this frame (depth_triangles.comp), when the object culls them
STIPPLE_CONST uint kBindingDepthTriangles = 19;
// DrawnPolygons header (its dispatch and count) + uint[] (storage): the polygons the density pass found
// large on screen this frame, for its gradient pass (density.comp, kSpecGradientPass)
STIPPLE_CONST uint kBindingGradientPolygons = 20;
// RG32UI texel view of the candidates (StippleVertex[], a candidate a texel), for the passes that read them at
// scattered places (the splat, the drawn list): one gather on a software GPU, where a storage buffer is
// loaded member by member, lane by lane
STIPPLE_CONST uint kBindingStippleTexels = 21;

// The compute splat's frame data (set 1). Plain buffers, one uint per pixel (row-major, top row
// first): a software rasteriser's image stores and image atomics cost several times its buffer ones.
STIPPLE_CONST uint kBindingSplatBackground = 0;  // uint[]: the frame's colour before the splat (read only)
STIPPLE_CONST uint kBindingSceneDepth = 1;       // uint[]: the depth pass's depth words (X8_D24 or float bits)
STIPPLE_CONST uint kBindingColorBuffer = 2;      // uint[]: the frame's colour, packed 8-bit channels
// uint[]: per pixel, the summed optical depth -log2(1 - intensity) of the large fractional stipples
// inked there this frame, in units of 1/kSplatOpticalDepthScale (zeroed before the splat; splat.comp)
STIPPLE_CONST uint kBindingSplatCover = 3;
// R32_UINT texel view of kBindingSceneDepth's words: a software GPU gathers texels, where it loads a storage
// buffer lane by lane
STIPPLE_CONST uint kBindingSceneDepthTexels = 4;
STIPPLE_CONST float kSplatOpticalDepthScale = 65536.0;
// A fractional stipple's optical depth is capped here: 2^-9 of paper left is under half a level of 8 bits.
STIPPLE_CONST float kSplatMaxOpticalDepth = 9.0;

// Bits of ObjectUniforms.flags.
STIPPLE_CONST uint kFlagShading = 1u;          // §2.2 (N.L)^n
STIPPLE_CONST uint kFlagExtrinsic = 2u;        // §2.3 extrinsic distance enhancement
STIPPLE_CONST uint kFlagIntrinsic = 4u;        // §2.3 intrinsic depth enhancement
STIPPLE_CONST uint kFlagRoundPoints = 8u;      // discard outside the disc for large points
STIPPLE_CONST uint kFlagBackfaceCull = 16u;    // polygons facing away get no stipples (§2.1)
STIPPLE_CONST uint kFlagToonFade = 32u;        // §3.1 stipples fade near the silhouette (toon mode)
STIPPLE_CONST uint kFlagTwoSided = 64u;        // polygons facing away are stippled with the flipped normal
STIPPLE_CONST uint kFlagFacingBits = 128u;     // the density pass writes the facing bits (kBindingFacing)
STIPPLE_CONST uint kFlagSilhouetteLines = 256u;  // §3.1 Raskar-Cohen lines (the indexed wide-line draw)
STIPPLE_CONST uint kFlagContours = 512u;       // object-space lines: edges between a front and a back face
STIPPLE_CONST uint kFlagBorders = 1024u;       // object-space lines: edges of one polygon
STIPPLE_CONST uint kFlagCreases = 2048u;       // object-space lines: dihedral angle above the crease angle
STIPPLE_CONST uint kFlagStretch = 4096u;       // animated: a polygon's due count follows its current area
STIPPLE_CONST uint kFlagCullOutsideView = 16384u;  // polygons wholly outside the view draw nothing (clip_outside_bits)
STIPPLE_CONST uint kFlagDepthOneSided = 8192u;  // the depth pass culls the faces facing away (depth_triangles.comp)
STIPPLE_CONST uint kFlagSolidDots = 32768u;    // a polygon's last stipple solid or absent by its threshold (solid_dot_intensity)

// One candidate stipple as the vertex stage reads it (vertex binding 0): 8 bytes. Its place is kept
// relative to its polygon, so it lies on the surface exactly (no quantisation off the depth pass's
// plane) and 16 bits per coordinate suffice at any model size: position = a + u (b - a) + v (c - a)
// for the triangle's corners a, b, c (shaders/stipple_position.h). Culled candidates, the many, never
// fetch the corners.
struct StippleVertex {
    uint barycentric;  // u | v << 16, 16-bit unorm (vertex format R16G16_UNORM)
    uint triangle;     // index into TriangleDraw/TriangleInfo and the mesh's triangles
};

// Per triangle and per frame: written by the density pass (GPU) or by the CPU path,
// read by stipple.vert to cull stipples beyond the density (§3.2).
struct TriangleDraw {
    float density;       // stipples to draw, fractional (§2.1: the last one at the fractional intensity)
    uint first_stipple;  // index of the triangle's first stipple in the stipple buffer
    // The least and the most density any point of the polygon sees (polygon_density_bounds in
    // stipple_formulas.h): both the density, but on a polygon large on screen, whose stipples are each drawn
    // at the density where they lie (stipple_density_here).
    float least;
    float most;
};

// Per triangle, constant for a static object (an animated one's are rewritten each frame from its
// deformed mesh by shaders/polygon_constants.comp): what the density computation reads, in one 16-byte
// load (a software GPU's compute is bound by its buffer loads). Unpacked by polygon_view() in stipple_formulas.h; the
// candidate count is the difference of consecutive TriangleDraw.first_stipple.
struct TriangleInfo {
    uint center_xy;           // centroid x | y << 16: 16-bit unorm in the object's box (ObjectUniforms.box_*)
    uint center_z_selection;  // centroid z | selection value << 16 (the fixed value of §2.3, 16 bits)
    uint normal;              // unit face normal (object space), octahedral, 2 x 16-bit snorm
    float area;               // object space
};

// The splat's work list: the polygons that draw at least one stipple this frame, appended by the
// density pass (or written by the CPU), then the splat dispatched over them alone. Most polygons of a
// dense mesh draw nothing (shading, probabilistic selection), so the splat skips them without a visit.
// Each item is a run of drawn stipples of one polygon (splat_run_length of them, the last one fewer),
// named by the index of its first stipple (its StippleVertex names the polygon): a polygon drawing k
// stipples has ceil(k / run) items, run >= kSplatShortRun, so a list holds at most polygons +
// candidates / kSplatShortRun of them.
// The header is a VkDispatchIndirectCommand (groups of kDensityWorkgroupSize) and the item count;
// the items follow it in the same buffer.
struct DrawnPolygons {
    uint groups_x;
    uint groups_y;
    uint groups_z;
    uint count;
};

// One edge of the mesh with the polygons on either side (§3.1 Raskar-Cohen lines; see
// src/render/silhouette_edges.hpp). A boundary edge has second_polygon == kNoPolygon.
STIPPLE_CONST uint kNoPolygon = 0xFFFFFFFFu;
struct SilhouetteEdge {
    uint first_vertex;
    uint second_vertex;
    uint first_polygon;
    uint second_polygon;
};

// A list that a compute pass appends indices to and a draw then reads: a VkDrawIndexedIndirectCommand,
// padding, then the indices. The buffer is bound as index buffer at offset 0 and the command's
// first_index (kIndexListFirstIndex) skips the header: lavapipe (Mesa 22.3) ignores the bound offset in
// indexed indirect draws, so a header skipped by that offset was drawn as four lines, the first from
// vertex 1 to vertex `index_count` (usually out of range: the origin).
//   SilhouetteLines: this frame's silhouette lines, the index pairs of the edges that border a
//     back-facing polygon.
//   DepthTriangles (kBindingDepthTriangles): the triangles the depth pass draws, three indices each.
//     Most triangles of a mesh finer than the pixels cover no pixel centre, produce no fragment and
//     change no depth, yet a software rasteriser sets each one up on its one geometry thread;
//     shaders/depth_triangles.comp leaves them out.
STIPPLE_CONST uint kIndexListHeaderBytes = 32;
STIPPLE_CONST uint kIndexListFirstIndex = kIndexListHeaderBytes / 4;
struct IndexList {
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
    uint pad0, pad1, pad2;
};
#ifdef __cplusplus
using SilhouetteLines = IndexList;
using DepthTriangles = IndexList;
#else
#define SilhouetteLines IndexList
#define DepthTriangles IndexList
#endif

// Depth by compute (shaders/depth_raster.comp, DepthRaster::Compute): the triangles its first pass
// leaves to the second, each one's box wider or taller than kRasterSmallSpan pixels or crossing the
// near plane. The header is a VkDispatchIndirectCommand (one workgroup per listed triangle, at most
// kRasterMaxGroups: Vulkan's least maxComputeWorkGroupCount) and the count; the triangle indices
// follow it (in the buffer of kBindingDepthTriangles, which the fixed-function pass's lists use).
STIPPLE_CONST uint kSpecRasterLarge = 0;  // depth_raster.comp: the pass over the listed triangles
// 96: the first pass's 32-bit edge values stay under 2^31 (2 * (97 * 256) * (96 * 256)); a lane per
// triangle up to this size beat a workgroup per triangle (docs/architecture.md, "Depth by compute").
STIPPLE_CONST uint kRasterSmallSpan = 96;
STIPPLE_CONST uint kRasterMaxGroups = 65535;
struct RasterTriangles {
    uint groups_x;
    uint groups_y;
    uint groups_z;
    uint count;
    uint pad0, pad1, pad2, pad3;
};

// Object-space lines (beyond the paper): line_edges.comp walks each contour, border and crease edge
// across the screen in pixel steps against the depth pass and appends the pieces it finds visible,
// in pixels (origin at the top-left corner, y down, as plot::Segment); line_pieces.vert draws each
// piece as a capsule. The header is a VkDrawIndirectCommand (6 vertices per piece appended, so it
// may exceed 6 * capacity: the pieces beyond the capacity are dropped, and their vertices culled).
STIPPLE_CONST uint kLineKindContour = 1u;  // the values of plot::LineKind (0 is the Raskar-Cohen silhouette)
STIPPLE_CONST uint kLineKindBorder = 2u;
STIPPLE_CONST uint kLineKindCrease = 3u;
// The edges with an object-space line this frame (line_edges.comp lists them, line_walk.comp walks
// them): a VkDispatchIndirectCommand (groups of kDensityWorkgroupSize) and the count, then one uint
// per edge: its index in the edge table, its kind in the top two bits.
STIPPLE_CONST uint kLineKindShift = 30u;
STIPPLE_CONST uint kLineEdgeMask = (1u << kLineKindShift) - 1u;
struct LineCandidates {
    uint groups_x;
    uint groups_y;
    uint groups_z;
    uint count;
};
struct LinePiecesHeader {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint first_instance;
    uint capacity;  // pieces the buffer holds after this header
    uint pad0, pad1, pad2;
};
struct LinePiece {
    float ax, ay, bx, by;  // the visible piece, pixels
    uint edge;             // index into the edge table (SilhouetteEdge)
    uint kind;             // kLineKind*
};

// What the counting variants record (kBindingDebug, kSpecCountDrawn): this header, then one bit per
// candidate stipple (set when it was drawn), 32 to a uint.
struct DebugCounters {
    uint drawn;  // stipples drawn this frame
    uint pad0, pad1, pad2;
};

// The stipples a frame drew, as vector output needs them (kSpecRecordVisible): each drawn stipple
// (index below its polygon's density, §3.2) that inked at least one pixel after the depth test
// (hidden-stipple removal, §2.1), at its exact window position, with its intensity (the last one's
// fraction, §2.1; the toon fade is in the density). At most one entry per candidate.
struct VisibleStipplesHeader {
    uint count;
    uint pad0, pad1, pad2;
};
struct VisibleStipple {
    float x, y;       // window pixels, origin top-left, y down (the PNG's)
    float intensity;  // (0, 1]
    uint index;       // the candidate (its polygon: ObjectGeometry::first_stipple)
    float scale;      // the dot's side over the point size: above 1 where the candidates cannot carry the
                      // density (stipple_scale), as the frame draws it
};

// One indirect draw, laid out as VkDrawIndirectCommand.
//
// The survivors' list of the indirect and cpu paths (kBindingDrawnStipples) starts with one: a draw of
// vertex_count points, one per stipple drawn this frame (index below its polygon's density, §3.2),
// whose candidate indices follow the command, one uint each (at most one per candidate). Culled
// candidates never reach the vertex stage, and one draw replaces a draw per polygon.
struct DrawCommand {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint first_instance;
};
// The vertex path's list in the same binding (kBindingDrawnStipples): a DrawCommand of kGradientChunk
// vertices and one instance per chunk (instance_count, counted by the gradient pass), then each chunk's
// first candidate: chunk k covers candidates [first, first + kGradientChunk) of its polygon, up to the most
// density any of them sees. At most one chunk per polygon plus one per kGradientChunk candidates.

struct FrameUniforms {
    mat4 view_proj;      // world -> clip
    mat4 view;           // world -> view (camera at origin looking down -z)
    vec4 light_view;     // xyz: unit direction toward the light, view space
    vec4 paper_color;    // rgb paper (background), a unused; the ink is each object's (ObjectUniforms::ink_color)
    vec4 viewport;       // width, height, 1/width, 1/height
    vec4 projection;     // x: pixels per world unit at unit distance (proj[1][1] * height / 2 / detail; in an
                         // orthographic view at every depth), for the densities; y: near; z: 1 for an
                         // orthographic view, else 0 (DensityParams::orthographic); w: detail scale
                         // (FrameView::detail_scale)
};

struct ObjectUniforms {
    mat4 model_view;        // object -> view
    mat4 normal_view;       // inverse transpose of model_view (upper 3x3 used)
    mat4 model_view_proj;   // object -> clip (the frame's view_proj times the object's model matrix, once per frame: a
                            // software GPU pays for each matrix product per vertex, culled ones included)
    vec4 shading;           // x: shading exponent n (§2.2); y: point size (px); z: toon sharpness (§3.1); w: unused
    vec4 extrinsic;         // x: pr; y: minimum stipple area (px^2); z: reference pixels per world unit; w: area scale (linear scale^2, object -> world)
    vec4 intrinsic;         // x: de; y: A, the object's depth half-range; z: view depth of the object's centre;
                            // w: 1 where the model matrix scales its axes unequally (polygon_view), else 0
    uvec4 flags;            // x: kFlag* bits; y: triangle count; z: silhouette edge count; w: candidate count
    vec4 box_min;           // xyz: corner of the object-space box the TriangleInfo centroids are quantised in
    vec4 box_size;          // xyz: the box's extent; w: how far a centroid quantised in it may lie from the true one, in
                            // view depth (DensityParams::near_margin)
    vec4 lines;             // x: line width px (thinned, §3.1); y: cosine of the crease angle; z: crease width px; w: unused
    vec4 ink_color;         // rgb: the object's ink (ObjectParams::ink, else the frame's); a unused
};

#ifdef __cplusplus
}  // namespace stipple::gpu
#endif

#endif
