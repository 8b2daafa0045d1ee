// Lines ink only the mesh's edges (issue 13), on every shared model, the default scene and a generated
// open bowl: the frame's Raskar-Cohen line list, read back as the indexed indirect draw reads it, holds
// only pairs of corners of one polygon, exactly the edges with a polygon facing away on one side and
// one facing the viewer (or none) on the other; every visible object-space piece (contours, borders,
// creases) lies on an edge of its kind; and no line ink of any kind lies farther than the line width
// outside the object's footprint. The stray segment of issue 13 was the list's header drawn as
// indices: lavapipe ignored the index buffer's bind offset in indirect draws, so the pair
// (index_count, instance_count) became a line from an out-of-range vertex (read as the origin) to
// vertex 1; see shared_types.h, SilhouetteLines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "mesh/load_mesh.hpp"
#include "render/density_formulas.hpp"
#include "render/silhouette_edges.hpp"
#include "stipple/selection_order.hpp"
#include "support/gpu_test.hpp"
#include "support/render_helpers.hpp"
#include "support/test_paths.hpp"
#include "support/test_shapes.hpp"

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class LineIntegrity : public test::GpuTest {};

// Every mesh of ../shared/models (each skipped with a message when absent; the animated ones in their
// rest pose: the fox is a triangle soup, the morph cube has split corners), the default scene, and a
// generated open bowl (empty path) whose inside the views look into.
std::vector<std::pair<std::string, std::string>> model_files() {
    std::vector<std::pair<std::string, std::string>> files;
    for (const char* name : {"stanford-bunny.obj", "horse.ply", "ogre.obj", "igea.ply", "spot.obj", "fox.glb",
                             "AnimatedMorphCube.gltf"}) {
        std::string path = test::shared_model(name);
        if (path.empty())
            std::printf("%s: absent from the shared models, skipped\n", name);
        else
            files.emplace_back(name, path);
    }
    files.emplace_back("blobby.glb", test::source_path("assets/blobby.glb"));
    files.emplace_back("open-bowl", "");
    return files;
}

struct Model {
    std::string name;
    test::Prepared object;
    std::unordered_set<uint64_t> edges;  // each side of each polygon, as smaller vertex << 32 | larger
    std::vector<gpu::SilhouetteEdge> table;  // the renderer's edge table, for the expected line count
};

uint64_t edge_key(uint32_t a, uint32_t b) { return uint64_t(std::min(a, b)) << 32 | std::max(a, b); }

// Loaded as the renderers draw it (draw order optimised); few stipples, which the lines do not depend on.
Model load_model(const std::string& name, const std::string& path) {
    ObjectParams params;
    params.generation.max_stipples = 20000;
    params.generation.relax_iterations = 0;
    Mesh mesh = path.empty() ? test::make_open_hemisphere(48, 16) : load_mesh_for_drawing(path);
    Model m{name, test::prepare(std::move(mesh), params), {}};
    // Ranked once here rather than by each renderer the model is added to (the costliest part of adding it).
    m.object.stipples.selection = polygon_selection_values(m.object.mesh, m.object.stipples, params.generation.seed);
    // The edges as the renderer keys them: corners at one position are one vertex.
    std::vector<uint32_t> indices = m.object.mesh.indices;
    const std::vector<uint32_t> welded = weld_by_position(m.object.mesh.positions);
    for (uint32_t& index : indices) index = welded[index];
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) m.edges.insert(edge_key(indices[t + k], indices[t + (k + 1) % 3]));
    m.table = build_silhouette_edges(indices);
    return m;
}

// The 16 views: yaw every 45 degrees, pitch +20 and -20.
struct ViewAngles {
    float yaw, pitch;
};
std::vector<ViewAngles> views() {
    std::vector<ViewAngles> v;
    for (float pitch : {20.0f, -20.0f})
        for (int k = 0; k < 8; ++k) v.push_back({45.0f * float(k), pitch});
    return v;
}

FrameView view_of(const Model& m, VkExtent2D extent, ViewAngles angles) {
    return test::framed_view(compute_bounding_sphere(m.object.mesh), extent, 1.0f, angles.yaw, angles.pitch);
}

// The last frame's line list as the draw reads it: the buffer is bound at offset 0 and the command's
// first_index and index_count select the indices (shared_types.h).
struct LineList {
    gpu::SilhouetteLines header{};
    std::vector<uint32_t> words;  // the whole buffer, header included
    std::vector<uint32_t> drawn;  // the indices the draw reads
};

LineList read_line_list(const gpu::Context& context, const ObjectGpu& object) {
    LineList list;
    std::vector<std::byte> bytes = gpu::read_buffer(context, object.frame.silhouette_lines);
    list.words.resize(bytes.size() / sizeof(uint32_t));
    std::memcpy(list.words.data(), bytes.data(), list.words.size() * sizeof(uint32_t));
    std::memcpy(&list.header, bytes.data(), sizeof list.header);
    const uint64_t begin = list.header.first_index, end = begin + list.header.index_count;
    if (end <= list.words.size()) list.drawn.assign(list.words.begin() + begin, list.words.begin() + end);
    return list;
}

// Whether each polygon faces away in the last frame, as the CPU evaluates the GPU's formula.
std::vector<bool> facing_away(const ObjectGpu& object) {
    std::vector<bool> away(object.geometry.triangle_count);
    for (size_t t = 0; t < away.size(); ++t) {
        auto p = formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), object.frame.uniforms);
        away[t] = formulas::polygon_faces_away(p.center, p.normal, formulas::DensityParams{});  // perspective
    }
    return away;
}

// What is wrong with a line list, or "" when every drawn pair is an edge of the mesh, the count is the
// CPU's count of edges between a polygon facing away and one that does not (or none), and the indices
// do not overlap the header.
std::string line_list_problem(const Model& m, const ObjectGpu& object, const LineList& list) {
    const gpu::SilhouetteLines& h = list.header;
    if (h.instance_count != 1 || h.vertex_offset != 0 || h.first_instance != 0)
        return "instance_count " + std::to_string(h.instance_count) + ", vertex_offset " +
               std::to_string(h.vertex_offset) + ", first_instance " + std::to_string(h.first_instance);
    if (uint64_t(h.first_index) * sizeof(uint32_t) < sizeof(gpu::SilhouetteLines))
        return "first_index " + std::to_string(h.first_index) + " draws the header as indices";
    if (uint64_t(h.first_index) + h.index_count > list.words.size())
        return "indices " + std::to_string(h.first_index) + " + " + std::to_string(h.index_count) +
               " beyond the buffer's " + std::to_string(list.words.size());
    if (h.index_count % 2 != 0) return "odd index count " + std::to_string(h.index_count);
    for (size_t i = 0; i < list.drawn.size(); i += 2)
        if (!m.edges.count(edge_key(list.drawn[i], list.drawn[i + 1])))
            return "line " + std::to_string(i / 2) + " joins vertices " + std::to_string(list.drawn[i]) + " and " +
                   std::to_string(list.drawn[i + 1]) + ", which share no polygon";
    size_t expected = 0;
    const std::vector<bool> away = facing_away(object);
    for (const auto& e : m.table) {
        const bool second = e.second_polygon != gpu::kNoPolygon;
        expected += formulas::raskar_cohen_edge(away[e.first_polygon], second, second && away[e.second_polygon]);
    }
    if (h.index_count != 2 * expected)
        return std::to_string(h.index_count / 2) + " lines drawn, " + std::to_string(expected) +
               " edges between a polygon facing away and one that does not";
    return "";
}

// What is wrong with the visible object-space pieces (contours, borders and creases all on), or "":
// each lies on the projection of its edge, and the edge is of the piece's kind (contour before crease).
std::string pieces_problem(const Model& m, const ObjectGpu& object, const StippleRenderer::LinePieces& pieces,
                           const FrameView& view) {
    if (pieces.appended != pieces.pieces.size())
        return std::to_string(pieces.appended) + " pieces found, " + std::to_string(pieces.pieces.size()) + " stored";
    const std::vector<bool> away = facing_away(object);
    const float cos_crease = std::cos(glm::radians(object.params.crease_angle));
    auto normal = [&](uint32_t t) {
        return formulas::polygon_view(object.polygons.cpu[t], 0.0f, object.frame.uniforms).normal;
    };
    const glm::mat4 mvp = object.frame.uniforms.model_view_proj;
    auto window = [&](uint32_t vertex) {
        glm::vec4 c = mvp * glm::vec4(m.object.mesh.positions[vertex], 1.0f);
        return glm::vec2((c.x / c.w + 1.0f) * 0.5f * float(view.extent.width),
                         (1.0f - c.y / c.w) * 0.5f * float(view.extent.height));
    };
    for (size_t i = 0; i < pieces.pieces.size(); ++i) {
        const gpu::LinePiece& p = pieces.pieces[i];
        const std::string where = "piece " + std::to_string(i) + " (edge " + std::to_string(p.edge) + ")";
        if (p.edge >= m.table.size()) return where + ": no such edge";
        const gpu::SilhouetteEdge& e = m.table[p.edge];
        const bool second = e.second_polygon != gpu::kNoPolygon;
        uint32_t kind = 0;
        if (formulas::contour_edge(away[e.first_polygon], second, second && away[e.second_polygon])) {
            kind = gpu::kLineKindContour;
        } else if (second) {
            // Within rounding of the crease angle either reading is right (the GPU decodes the normals in
            // object space, this in view space).
            float c = glm::dot(normal(e.first_polygon), normal(e.second_polygon));
            if (std::abs(c - cos_crease) < 1e-4f) continue;
            if (c < cos_crease) kind = gpu::kLineKindCrease;
        } else {
            kind = gpu::kLineKindBorder;
        }
        if (p.kind != kind)
            return where + " drawn as kind " + std::to_string(p.kind) + ", the CPU says " + std::to_string(kind);
        // On the projected edge: both ends within a hundredth of a pixel of the segment.
        glm::vec2 a = window(e.first_vertex), b = window(e.second_vertex);
        for (glm::vec2 q : {glm::vec2(p.ax, p.ay), glm::vec2(p.bx, p.by)}) {
            float t = glm::clamp(glm::dot(q - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-12f), 0.0f, 1.0f);
            float off = glm::distance(q, a + t * (b - a));
            if (off > 0.01f * std::max(1.0f, glm::distance(a, b)))
                return where + " lies " + std::to_string(off) + " px off its edge";
        }
    }
    return "";
}

std::vector<uint64_t> sorted_lines(const LineList& list) {
    std::vector<uint64_t> lines;
    for (size_t i = 0; i + 1 < list.drawn.size(); i += 2) lines.push_back(edge_key(list.drawn[i], list.drawn[i + 1]));
    std::sort(lines.begin(), lines.end());
    return lines;
}

TEST_F(LineIntegrity, LineListsHoldOnlyEdgesOfTheMesh) {
    ObjectParams params;
    params.silhouette_lines = true;
    params.contours = params.borders = params.creases = true;
    bool resolution_checked = false;
    for (const auto& [name, path] : model_files()) {
        Model m = load_model(name, path);
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(m.object.mesh, m.object.stipples, m.object.model, params);
        // The list does not depend on the resolution (polygons face away in view space), so the views
        // are drawn small; checked once against a 4x larger frame of the same aspect.
        OffscreenTarget target(*context, {160, 128});
        if (!resolution_checked) {
            OffscreenTarget large(*context, {640, 512});
            for (ViewAngles a : {ViewAngles{45.0f, 20.0f}, ViewAngles{270.0f, -20.0f}}) {
                target.draw(renderer, view_of(m, target.extent(), a));
                std::vector<uint64_t> small_lines = sorted_lines(read_line_list(*context, renderer.object(0)));
                large.draw(renderer, view_of(m, large.extent(), a));
                std::vector<uint64_t> large_lines = sorted_lines(read_line_list(*context, renderer.object(0)));
                EXPECT_EQ(small_lines, large_lines) << name << " yaw " << a.yaw << " pitch " << a.pitch
                                                    << ": the line list changes with the resolution";
                std::printf("%s yaw %.0f pitch %.0f: %zu lines at 160x128, %zu at 640x512, %s\n", name.c_str(), a.yaw,
                            a.pitch, small_lines.size(), large_lines.size(),
                            small_lines == large_lines ? "the same" : "DIFFERENT");
            }
            resolution_checked = true;
        }
        // Every view with the default path, two with each other path: the lines do not depend on the
        // path, but each records different passes before them.
        size_t frames = 0, lines = 0, pieces = 0;
        std::vector<std::string> problems;
        for (DensityPath density_path : kAllDensityPaths) {
            renderer.params(0).density_path = density_path;
            std::vector<ViewAngles> angles = views();
            if (density_path != ObjectParams{}.density_path) angles = {angles[1], angles[8 + 5]};
            for (ViewAngles a : angles) {
                const FrameView view = view_of(m, target.extent(), a);
                target.draw(renderer, view);
                LineList list = read_line_list(*context, renderer.object(0));
                StippleRenderer::LinePieces visible = renderer.read_line_pieces(0);
                std::string problem = line_list_problem(m, renderer.object(0), list);
                if (problem.empty()) problem = pieces_problem(m, renderer.object(0), visible, view);
                if (!problem.empty())
                    problems.push_back(std::string(density_path_name(density_path)) + " yaw " +
                                       std::to_string(int(a.yaw)) + " pitch " + std::to_string(int(a.pitch)) + ": " +
                                       problem);
                ++frames;
                lines += list.header.index_count / 2;
                pieces += visible.pieces.size();
            }
        }
        std::printf("%s: %zu vertices, %zu polygons; %zu frames (16 views, 2 more per other path), %zu Raskar-Cohen "
                    "lines, %zu object-space pieces, %zu frames wrong\n",
                    name.c_str(), m.object.mesh.positions.size(), m.object.mesh.triangle_count(), frames, lines,
                    pieces, problems.size());
        for (size_t i = 0; i < std::min<size_t>(problems.size(), 3); ++i) std::printf("  %s\n", problems[i].c_str());
        EXPECT_TRUE(problems.empty()) << name << ": " << problems.size() << " frames draw a wrong line list, e.g. "
                                      << problems.front();
    }
}

// The object's footprint: pixels its front faces cover (depth < 1) or its back faces do, seen through
// a hole of an open mesh (the bunny's base, igea's neck), where Raskar-Cohen rightly inks the back
// faces' edges. The back faces are the front faces of the mesh with its winding reversed.
Mesh reversed_winding(const Mesh& mesh) {
    Mesh reversed = mesh;
    for (size_t t = 0; t + 2 < reversed.indices.size(); t += 3) std::swap(reversed.indices[t + 1], reversed.indices[t + 2]);
    return reversed;
}

struct OutsideInk {
    size_t far = 0;   // ink farther than the line width (and a pixel) from the footprint
    size_t near = 0;  // ink outside the footprint but within that reach (a line's outer half)
};

// Marks the far pixels red in `image` (for a person to look at). The footprint is sampled at pixel
// centres: a polygon seen edge-on, thinner than a pixel, covers none, and a line on its edge lies up
// to a pixel beyond the covered centres; hence a pixel's slack beyond the line width.
OutsideInk outside_ink(Image& image, const std::vector<float>& depth, const std::vector<float>& back_depth,
                       int width, int height, float line_width) {
    auto in_footprint = [&](int x, int y) {
        size_t i = size_t(y) * width + x;
        return depth[i] < 1.0f || back_depth[i] < 1.0f;
    };
    const float allowed = line_width + 1.0f;
    const int reach = int(std::ceil(allowed));
    OutsideInk ink;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            uint8_t* p = &image.pixels[4 * (size_t(y) * width + x)];
            if (p[0] >= 128 || in_footprint(x, y)) continue;
            bool near = false;
            for (int dy = -reach; dy <= reach && !near; ++dy)
                for (int dx = -reach; dx <= reach && !near; ++dx) {
                    int u = x + dx, v = y + dy;
                    near = float(dx * dx + dy * dy) <= allowed * allowed && u >= 0 && v >= 0 && u < width &&
                           v < height && in_footprint(u, v);
                }
            if (near) {
                ++ink.near;
            } else {
                ++ink.far;
                p[0] = 255, p[1] = 0, p[2] = 0;
            }
        }
    return ink;
}

// Each kind of line alone, then all of them at once, by name and switch.
struct LineKindCase {
    const char* name;
    void (*set)(ObjectParams&);
};
const LineKindCase kLineKindCases[] = {
    {"silhouette lines", [](ObjectParams& p) { p.silhouette_lines = true; }},
    {"contours", [](ObjectParams& p) { p.contours = true; }},
    {"borders", [](ObjectParams& p) { p.borders = true; }},
    {"creases", [](ObjectParams& p) { p.creases = true; }},
    {"all lines", [](ObjectParams& p) { p.silhouette_lines = p.contours = p.borders = p.creases = true; }},
};

TEST_F(LineIntegrity, LineInkStaysWithinTheLineWidthOfTheFootprint) {
    const VkExtent2D extent{480, 384};
    OffscreenTarget target(*context, extent);
    for (const auto& [name, path] : model_files()) {
        Model m = load_model(name, path);
        StippleRenderer back(*context, kColorFormat, context->depth_format);
        back.add_object(reversed_winding(m.object.mesh), m.object.stipples, m.object.model, ObjectParams{});
        // On the default path the paper's lines from all 16 views and every other kind, alone and all at
        // once, from 8 (yaw every 45 degrees, pitch +20 and -20 in turn); all kinds at once on every
        // other path from two views (the lines do not depend on the path, but each records different
        // passes).
        std::vector<std::pair<DensityPath, const LineKindCase*>> cases;
        for (const LineKindCase& kind : kLineKindCases) cases.emplace_back(ObjectParams{}.density_path, &kind);
        for (DensityPath density_path : kAllDensityPaths)
            if (density_path != ObjectParams{}.density_path) cases.emplace_back(density_path, &kLineKindCases[4]);
        std::vector<std::unique_ptr<StippleRenderer>> renderers;  // one per case, kept across the views
        for (const auto& [density_path, kind] : cases) {
            ObjectParams params;
            params.density_path = density_path;
            kind->set(params);
            renderers.push_back(std::make_unique<StippleRenderer>(*context, kColorFormat, context->depth_format));
            renderers.back()->add_object(m.object.mesh, m.object.stipples, m.object.model, params);
        }
        OutsideInk worst;
        ViewAngles worst_view{};
        std::string worst_case;
        Image worst_image;
        float width = 0.0f;
        size_t frames = 0;
        const std::vector<ViewAngles> all_views = views();
        for (size_t v = 0; v < all_views.size(); ++v) {
            const ViewAngles a = all_views[v];
            FrameView view = view_of(m, extent, a);
            std::vector<float> back_depth;  // the footprint's back faces, drawn once per view
            const bool alternate = (v < 8) == (v % 2 == 0);  // pitch +20 at even yaw steps, -20 at odd ones
            for (size_t c = 0; c < cases.size(); ++c) {
                const auto& [density_path, kind] = cases[c];
                const bool default_path = density_path == ObjectParams{}.density_path;
                const bool drawn = default_path ? (c == 0 || alternate) : (v == 1 || v == 13);
                if (!drawn) continue;
                if (back_depth.empty()) back_depth = target.render(back, view).depth;
                RenderedFrame frame = target.render(*renderers[c], view);
                width = renderers[c]->object(0).frame.line_width;
                OutsideInk ink = outside_ink(frame.color, frame.depth, back_depth, int(extent.width),
                                             int(extent.height), width);
                ++frames;
                if (worst_image.pixels.empty() || ink.far > worst.far || (ink.far == worst.far && ink.near > worst.near))
                    worst = ink, worst_view = a, worst_image = frame.color,
                    worst_case = std::string(density_path_name(density_path)) + ", " + kind->name;
            }
        }
        const std::string image = "line_integrity_" + name.substr(0, name.find('.')) + ".png";
        write_png(test::output_path(image).string(), worst_image);
        std::printf("%s: line width %.2f px; %zu frames; worst: %s, yaw %.0f pitch %.0f: %zu ink px beyond the line "
                    "width and a pixel outside the footprint (red in %s), %zu within it\n",
                    name.c_str(), width, frames, worst_case.c_str(), worst_view.yaw, worst_view.pitch, worst.far,
                    test::output_path(image).c_str(), worst.near);
        EXPECT_EQ(worst.far, 0u) << name << " " << worst_case << " yaw " << worst_view.yaw << " pitch " << worst_view.pitch;
    }
}

}  // namespace
}  // namespace stipple
