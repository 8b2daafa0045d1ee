// Raskar-Cohen lines (§3.1) ink only the mesh's edges (issue 13): the frame's line list, read back as
// the indexed indirect draw reads it, holds only pairs of corners of one polygon, and no line ink lies
// farther than the line width outside the object's footprint. The stray segment of issue 13 was the
// list's header drawn as indices: lavapipe ignored the index buffer's bind offset in indirect draws,
// so the pair (index_count, instance_count) became a line from an out-of-range vertex (read as the
// origin) to vertex 1; see shared_types.h, SilhouetteLines.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
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

namespace stipple {
namespace {

// Every GPU test of this file shares one fixture name, so a failure names its suite.
class LineIntegrity : public test::GpuTest {};

// Every static mesh of ../shared/models (each skipped with a message when absent) and the default scene.
std::vector<std::pair<std::string, std::string>> model_files() {
    std::vector<std::pair<std::string, std::string>> files;
    for (const char* name : {"stanford-bunny.obj", "horse.ply", "ogre.obj", "igea.ply", "spot.obj"}) {
        std::string path = test::shared_model(name);
        if (path.empty())
            std::printf("%s: absent from the shared models, skipped\n", name);
        else
            files.emplace_back(name, path);
    }
    files.emplace_back("blobby.glb", std::string(STIPPLE_SOURCE_DIR) + "/assets/blobby.glb");
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
    Model m{name, test::prepare(load_mesh_for_drawing(path), params), {}};
    // Ranked once here rather than by each renderer the model is added to (the costliest part of adding it).
    m.object.stipples.selection = polygon_selection_values(m.object.mesh, params.generation.seed);
    const std::vector<uint32_t>& indices = m.object.mesh.indices;
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

// What is wrong with a line list, or "" when every drawn pair is an edge of the mesh, the count is the
// CPU's count of edges bordering a polygon that faces away, and the indices do not overlap the header.
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
    auto away = [&](uint32_t t) {
        auto p = formulas::polygon_view(object.polygons.cpu[t], object.geometry.candidates(t), object.frame.uniforms);
        return formulas::polygon_faces_away(p.center, p.normal);
    };
    for (const auto& e : m.table)
        expected += away(e.first_polygon) || (e.second_polygon != gpu::kNoPolygon && away(e.second_polygon));
    if (h.index_count != 2 * expected)
        return std::to_string(h.index_count / 2) + " lines drawn, " + std::to_string(expected) + " edges border a polygon facing away";
    return "";
}

std::vector<uint64_t> sorted_lines(const LineList& list) {
    std::vector<uint64_t> lines;
    for (size_t i = 0; i + 1 < list.drawn.size(); i += 2) lines.push_back(edge_key(list.drawn[i], list.drawn[i + 1]));
    std::sort(lines.begin(), lines.end());
    return lines;
}

TEST_F(LineIntegrity, LineListHoldsOnlyEdgesOfTheMesh) {
    ObjectParams params;
    params.silhouette_lines = true;
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
        size_t frames = 0, lines = 0;
        std::vector<std::string> problems;
        for (DensityPath density_path : kAllDensityPaths) {
            renderer.params(0).density_path = density_path;
            std::vector<ViewAngles> angles = views();
            if (density_path != ObjectParams{}.density_path) angles = {angles[1], angles[8 + 5]};
            for (ViewAngles a : angles) {
                target.draw(renderer, view_of(m, target.extent(), a));
                LineList list = read_line_list(*context, renderer.object(0));
                std::string problem = line_list_problem(m, renderer.object(0), list);
                if (!problem.empty())
                    problems.push_back(std::string(density_path_name(density_path)) + " yaw " +
                                       std::to_string(int(a.yaw)) + " pitch " + std::to_string(int(a.pitch)) + ": " +
                                       problem);
                ++frames;
                lines += list.header.index_count / 2;
            }
        }
        std::printf("%s: %zu vertices, %zu polygons; %zu frames (16 views, 2 more per other path), %zu lines, %zu frames wrong\n",
                    name.c_str(), m.object.mesh.positions.size(), m.object.mesh.triangle_count(), frames, lines,
                    problems.size());
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
    size_t far = 0;   // ink farther than the line width from the footprint
    size_t near = 0;  // ink outside the footprint but within the line width (a line's outer half)
};

// Marks the far pixels red in `image` (for a person to look at).
OutsideInk outside_ink(Image& image, const std::vector<float>& depth, const std::vector<float>& back_depth,
                       int width, int height, float line_width) {
    auto in_footprint = [&](int x, int y) {
        size_t i = size_t(y) * width + x;
        return depth[i] < 1.0f || back_depth[i] < 1.0f;
    };
    const int reach = int(std::ceil(line_width));
    OutsideInk ink;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            uint8_t* p = &image.pixels[4 * (size_t(y) * width + x)];
            if (p[0] >= 128 || in_footprint(x, y)) continue;
            bool near = false;
            for (int dy = -reach; dy <= reach && !near; ++dy)
                for (int dx = -reach; dx <= reach && !near; ++dx) {
                    int u = x + dx, v = y + dy;
                    near = float(dx * dx + dy * dy) <= line_width * line_width && u >= 0 && v >= 0 && u < width &&
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

TEST_F(LineIntegrity, LineInkStaysWithinTheLineWidthOfTheFootprint) {
    ObjectParams params;  // the default density path
    params.silhouette_lines = true;
    ObjectParams back_params;
    const VkExtent2D extent{480, 384};
    OffscreenTarget target(*context, extent);
    for (const auto& [name, path] : model_files()) {
        Model m = load_model(name, path);
        StippleRenderer renderer(*context, kColorFormat, context->depth_format);
        renderer.add_object(m.object.mesh, m.object.stipples, m.object.model, params);
        StippleRenderer back(*context, kColorFormat, context->depth_format);
        back.add_object(reversed_winding(m.object.mesh), m.object.stipples, m.object.model, back_params);
        OutsideInk worst;
        ViewAngles worst_view{};
        Image worst_image;
        float width = 0.0f;
        for (ViewAngles a : views()) {
            FrameView view = view_of(m, extent, a);
            RenderedFrame frame = target.render(renderer, view);
            width = renderer.object(0).frame.line_width;
            std::vector<float> back_depth = target.render(back, view).depth;
            OutsideInk ink = outside_ink(frame.color, frame.depth, back_depth, int(extent.width), int(extent.height), width);
            if (worst_image.pixels.empty() || ink.far > worst.far || (ink.far == worst.far && ink.near > worst.near))
                worst = ink, worst_view = a, worst_image = frame.color;
        }
        const std::string image = "line_integrity_" + name.substr(0, name.find('.')) + ".png";
        write_png(test::output_path(image).string(), worst_image);
        std::printf("%s: line width %.2f px; worst view yaw %.0f pitch %.0f: %zu ink px beyond the line width outside "
                    "the footprint (red in %s), %zu within it\n",
                    name.c_str(), width, worst_view.yaw, worst_view.pitch, worst.far, test::output_path(image).c_str(),
                    worst.near);
        EXPECT_EQ(worst.far, 0u) << name << " yaw " << worst_view.yaw << " pitch " << worst_view.pitch;
    }
}

}  // namespace
}  // namespace stipple
