// make_blobby OUT.glb
//
// Generates assets/blobby.glb, the project's built-in default scene: a "blobby" metaball surface
// like the one in Figure 1 of Lu et al. (VMV 2002). A handful of hand-placed metaballs of varied
// radii define an implicit field; its iso-surface is polygonised with marching tetrahedra on a
// Kuhn (Freudenthal) subdivision of a regular grid, relaxed tangentially for well-shaped
// triangles, and written as a binary glTF with POSITION (min/max), NORMAL and uint32 indices.
//
// Everything is deterministic: fixed inputs, fixed visiting order, no hashing order exposed, and
// only + - * / sqrt on doubles (all correctly rounded in IEEE 754), so the same build produces the
// same bytes every run (tests/test_blobby_asset.cpp checks this).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>
#include <meshoptimizer.h>
// libtinygltf.so (Debian's libtinygltf-dev) carries the implementation: the header alone is
// included here, without TINYGLTF_IMPLEMENTATION.
#include <tiny_gltf.h>

#include "core/error.hpp"

namespace {

using dvec3 = glm::dvec3;

// ---------------------------------------------------------------------------------------------
// The implicit field.

struct Ball {
    dvec3 center;
    double radius;  // influence radius R: the kernel is zero beyond it
};

// Hand-placed, deliberately asymmetric: a large body with lobes of varied size around it, close
// enough to merge into one smooth lumpy surface but far enough apart that each lobe stays visible
// (creases where lobes meet are what make stipple shading interesting). Pushing the small bumps
// further out first thins their necks (weak gradient, see kMinSurfaceGradient) and then detaches
// them; check_single_sphere() refuses either.
constexpr std::array<Ball, 8> kBalls{{
    {{0.00, 0.00, 0.00}, 1.15},     // main body
    {{0.58, 0.36, 0.12}, 0.88},     // upper-right lobe
    {{-0.56, 0.28, -0.20}, 0.80},   // upper-left lobe
    {{0.16, -0.58, 0.32}, 0.76},    // lower-front lobe
    {{-0.34, -0.48, -0.40}, 0.66},  // lower-back lobe
    {{0.26, 0.72, -0.40}, 0.60},    // small top bump
    {{-0.70, -0.10, 0.42}, 0.58},   // small left-front bump
    {{0.74, -0.26, -0.34}, 0.56},   // small right-back bump
}};

// Iso-level of the summed kernels; a lone ball's surface sits at R * sqrt(1 - kIso^(1/3)) ~ 0.45 R.
constexpr double kIso = 0.5;
// Lower bound on |grad field| over the surface (a lone ball gives about 1.7 / R).
constexpr double kMinSurfaceGradient = 0.5;

// Wyvill-style polynomial kernel (1 - r^2/R^2)^3: smooth (C^1 at R), compact, and evaluated with
// multiplications only, which keeps the output bit-for-bit reproducible across libm versions.
double field(const dvec3& p) {
    double sum = 0.0;
    for (const Ball& b : kBalls) {
        const dvec3 d = p - b.center;
        const double q = 1.0 - glm::dot(d, d) / (b.radius * b.radius);
        if (q > 0.0) sum += q * q * q;
    }
    return sum;
}

dvec3 gradient(const dvec3& p) {
    dvec3 g(0.0);
    for (const Ball& b : kBalls) {
        const dvec3 d = p - b.center;
        const double r2 = b.radius * b.radius;
        const double q = 1.0 - glm::dot(d, d) / r2;
        if (q > 0.0) g += (-6.0 * q * q / r2) * d;
    }
    return g;
}

// The field grows inward, so the outward normal is the normalised negative gradient.
dvec3 outward_normal(const dvec3& p) {
    const dvec3 g = gradient(p);
    const double len2 = glm::dot(g, g);
    STIPPLE_CHECK(len2 > 1e-24, "field gradient vanishes on the surface");
    return -g / std::sqrt(len2);
}

// Newton steps along the gradient onto field == kIso.
dvec3 project_to_surface(dvec3 p) {
    for (int i = 0; i < 4; ++i) {
        const dvec3 g = gradient(p);
        const double len2 = glm::dot(g, g);
        if (len2 < 1e-24) break;
        p -= ((field(p) - kIso) / len2) * g;
    }
    return p;
}

// ---------------------------------------------------------------------------------------------
// Marching tetrahedra.

struct Surface {
    std::vector<dvec3> positions;
    std::vector<uint32_t> indices;
};

// Grid resolution: cells along the longest side of the field's support. Chosen so that the
// asset stays under the repository's 1 MiB limit with 32-bit floats and indices.
constexpr int kCellsAlongLongestSide = 60;

// Kuhn subdivision of a cube into 6 tetrahedra, one per axis permutation (a, b, c):
// corners 0, e_a, e_a + e_b, 7 (corner bits: x = 1, y = 2, z = 4). Every face diagonal runs from
// the face's lowest to its highest corner, so neighbouring cubes agree on shared faces and the
// polygonised surface is watertight. Every tetrahedron edge goes from a corner to one that is
// greater or equal in every coordinate, which gives each edge a canonical (low, offset) key.
constexpr std::array<std::array<int, 3>, 6> kAxisPermutations{
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

int permutation_parity(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (p[i] > p[j]) ++inversions;
    return (inversions % 2 == 0) ? 1 : -1;
}

Surface polygonise() {
    dvec3 lo(1e30), hi(-1e30);
    for (const Ball& b : kBalls) {
        lo = glm::min(lo, b.center - dvec3(b.radius));
        hi = glm::max(hi, b.center + dvec3(b.radius));
    }
    const dvec3 extent = hi - lo;
    const double h = std::max({extent.x, extent.y, extent.z}) / kCellsAlongLongestSide;
    // One empty cell of margin on each side: every boundary sample is outside (field 0), so the
    // surface cannot touch the grid's border and comes out closed.
    const dvec3 origin = lo - dvec3(h);
    const int nx = static_cast<int>(std::ceil(extent.x / h)) + 3;
    const int ny = static_cast<int>(std::ceil(extent.y / h)) + 3;
    const int nz = static_cast<int>(std::ceil(extent.z / h)) + 3;
    auto grid_index = [&](int x, int y, int z) { return (static_cast<int64_t>(z) * ny + y) * nx + x; };
    auto grid_point = [&](int x, int y, int z) { return origin + h * dvec3(x, y, z); };

    std::vector<double> values(static_cast<size_t>(nx) * ny * nz);
    for (int z = 0; z < nz; ++z)
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) values[grid_index(x, y, z)] = field(grid_point(x, y, z));

    Surface s;
    // Vertices are keyed by the grid edge they lie on (low end * 8 + corner offset), so the two
    // to six tetrahedra that share an edge share the vertex: welding is exact, not by distance.
    std::unordered_map<int64_t, uint32_t> edge_vertex;
    std::array<int64_t, 8> corner_index{};
    std::array<double, 8> corner_value{};
    std::array<glm::ivec3, 8> corner_cell{};

    auto vertex_on_edge = [&](int a, int b) -> uint32_t {
        if ((a & b) != a) std::swap(a, b);  // a is now the low end: its bits are a subset of b's
        const int64_t key = corner_index[a] * 8 + (b ^ a);
        const auto [it, inserted] = edge_vertex.try_emplace(key, static_cast<uint32_t>(s.positions.size()));
        if (inserted) {
            // Always interpolated from the low end, so the result cannot depend on which
            // tetrahedron reached this edge first. The clamp keeps vertices on neighbouring edges
            // apart when a sample lies almost exactly on the iso-level; relaxation and projection
            // put them back on the surface.
            const double t = std::clamp((kIso - corner_value[a]) / (corner_value[b] - corner_value[a]), 0.02, 0.98);
            const dvec3 pa = grid_point(corner_cell[a].x, corner_cell[a].y, corner_cell[a].z);
            const dvec3 pb = grid_point(corner_cell[b].x, corner_cell[b].y, corner_cell[b].z);
            s.positions.push_back(pa + t * (pb - pa));
        }
        return it->second;
    };
    auto emit = [&](uint32_t a, uint32_t b, uint32_t c) { s.indices.insert(s.indices.end(), {a, b, c}); };

    for (int z = 0; z + 1 < nz; ++z)
        for (int y = 0; y + 1 < ny; ++y)
            for (int x = 0; x + 1 < nx; ++x) {
                int inside_mask = 0;
                for (int c = 0; c < 8; ++c) {
                    corner_cell[c] = {x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1)};
                    corner_index[c] = grid_index(corner_cell[c].x, corner_cell[c].y, corner_cell[c].z);
                    corner_value[c] = values[corner_index[c]];
                    if (corner_value[c] > kIso) inside_mask |= 1 << c;
                }
                if (inside_mask == 0 || inside_mask == 0xff) continue;

                for (const auto& axes : kAxisPermutations) {
                    const int ea = 1 << axes[0], eb = 1 << axes[1];
                    const std::array<int, 4> tet{0, ea, ea | eb, 7};
                    // det(e_a, e_a + e_b, e_a + e_b + e_c) = det(e_a, e_b, e_c): the tetrahedron's
                    // orientation is the parity of its axis permutation.
                    const int tet_sign = permutation_parity({axes[0], axes[1], axes[2], 3});

                    std::array<int, 4> in{}, out{};
                    int n_in = 0, n_out = 0;
                    for (int i = 0; i < 4; ++i) {
                        if (inside_mask & (1 << tet[i])) in[n_in++] = i;
                        else out[n_out++] = i;
                    }
                    if (n_in == 0 || n_in == 4) continue;

                    // Reorder the tetrahedron as p = (lone vertex or inside pair, rest) and make
                    // that order positively oriented by swapping its last two entries if needed.
                    std::array<int, 4> p{};
                    if (n_in == 1) p = {in[0], out[0], out[1], out[2]};
                    else if (n_in == 3) p = {out[0], in[0], in[1], in[2]};
                    else p = {in[0], in[1], out[0], out[1]};
                    if (tet_sign * permutation_parity(p) < 0) std::swap(p[2], p[3]);
                    const int v0 = tet[p[0]], v1 = tet[p[1]], v2 = tet[p[2]], v3 = tet[p[3]];

                    // For a positive tetrahedron (v0..v3) the triangle (v0v1, v0v2, v0v3) faces away
                    // from v0, and the quad (v0v2, v0v3, v1v3, v1v2) faces away from v0 and v1.
                    // Outward means from inside (field > iso) to outside.
                    if (n_in == 1) {
                        emit(vertex_on_edge(v0, v1), vertex_on_edge(v0, v2), vertex_on_edge(v0, v3));
                    } else if (n_in == 3) {
                        emit(vertex_on_edge(v0, v1), vertex_on_edge(v0, v3), vertex_on_edge(v0, v2));
                    } else {
                        const uint32_t q0 = vertex_on_edge(v0, v2), q1 = vertex_on_edge(v0, v3);
                        const uint32_t q2 = vertex_on_edge(v1, v3), q3 = vertex_on_edge(v1, v2);
                        // Split along the shorter diagonal for better-shaped triangles; either
                        // split is interior to this tetrahedron, so topology is unaffected.
                        const dvec3 d02 = s.positions[q2] - s.positions[q0];
                        const dvec3 d13 = s.positions[q3] - s.positions[q1];
                        if (glm::dot(d02, d02) <= glm::dot(d13, d13)) {
                            emit(q0, q1, q2);
                            emit(q0, q2, q3);
                        } else {
                            emit(q0, q1, q3);
                            emit(q1, q2, q3);
                        }
                    }
                }
            }
    return s;
}

// ---------------------------------------------------------------------------------------------
// Relaxation: marching tetrahedra leaves many slivers. Moving every vertex toward the mean of its
// neighbours within the tangent plane, then back onto the iso-surface, evens out the triangles
// without changing connectivity (so the mesh stays closed) or the shape.

void relax(Surface& s, int iterations) {
    std::vector<std::vector<uint32_t>> neighbours(s.positions.size());
    for (size_t t = 0; t < s.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            neighbours[s.indices[t + k]].push_back(s.indices[t + (k + 1) % 3]);
            neighbours[s.indices[t + k]].push_back(s.indices[t + (k + 2) % 3]);
        }
    for (auto& n : neighbours) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    std::vector<dvec3> next(s.positions.size());
    for (int it = 0; it < iterations; ++it) {
        for (size_t v = 0; v < s.positions.size(); ++v) {  // Jacobi: reads only the old positions
            const dvec3 p = s.positions[v];
            dvec3 mean(0.0);
            for (uint32_t n : neighbours[v]) mean += s.positions[n];
            mean /= static_cast<double>(neighbours[v].size());
            const dvec3 normal = outward_normal(p);
            dvec3 move = mean - p;
            move -= glm::dot(move, normal) * normal;
            next[v] = project_to_surface(p + 0.5 * move);
        }
        s.positions.swap(next);
    }
}

// ---------------------------------------------------------------------------------------------
// Checks the tool refuses to write a file without.

// Closed and consistently wound: every directed edge appears once and its reverse once.
void check_closed(const Surface& s) {
    std::vector<uint64_t> directed;
    directed.reserve(s.indices.size());
    for (size_t t = 0; t < s.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k)
            directed.push_back(uint64_t(s.indices[t + k]) << 32 | s.indices[t + (k + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    STIPPLE_CHECK(std::adjacent_find(directed.begin(), directed.end()) == directed.end(),
                  "a directed edge is used twice (non-manifold or inconsistent winding)");
    for (uint64_t e : directed) {
        const uint64_t reverse = (e << 32) | (e >> 32);
        STIPPLE_CHECK(std::binary_search(directed.begin(), directed.end(), reverse), "open edge");
    }
}

// Every face normal agrees with the field's outward normal at the face centre.
void check_orientation(const Surface& s) {
    for (size_t t = 0; t < s.indices.size(); t += 3) {
        const dvec3 a = s.positions[s.indices[t]], b = s.positions[s.indices[t + 1]],
                    c = s.positions[s.indices[t + 2]];
        const dvec3 n = glm::cross(b - a, c - a);
        STIPPLE_CHECK(glm::dot(n, n) > 0.0, "degenerate triangle");
        STIPPLE_CHECK(glm::dot(n, outward_normal((a + b + c) / 3.0)) > 0.0, "triangle faces inward");
    }
}

// One piece, topologically a sphere (Euler characteristic V - E + F = 2 with E = 3F/2): the
// balls must merge into a single blob rather than leave a detached droplet or a pinched handle.
void check_single_sphere(const Surface& s) {
    std::vector<uint32_t> parent(s.positions.size());
    for (uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
    auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (size_t t = 0; t < s.indices.size(); t += 3)
        for (int k = 1; k < 3; ++k) parent[root(s.indices[t + k])] = root(s.indices[t]);
    size_t components = 0;
    for (uint32_t v = 0; v < parent.size(); ++v) components += (root(v) == v);
    STIPPLE_CHECK(components == 1, "surface has " + std::to_string(components) + " pieces");
    const int64_t euler = int64_t(s.positions.size()) - int64_t(s.indices.size() / 3) / 2;
    STIPPLE_CHECK(euler == 2, "surface is not a sphere (Euler characteristic " + std::to_string(euler) + ")");
}

// The weakest field gradient on the surface: near zero means a pinch point or a neck about to
// form, where the polygonisation is ill-conditioned. The ball layout is tuned to keep it high.
double min_surface_gradient(const Surface& s) {
    double weakest = 1e30;
    for (const dvec3& p : s.positions) weakest = std::min(weakest, glm::length(gradient(p)));
    return weakest;
}

// ---------------------------------------------------------------------------------------------
// Output.

template <class T>
void append_bytes(std::vector<unsigned char>& out, const std::vector<T>& data) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    out.insert(out.end(), bytes, bytes + data.size() * sizeof(T));
}

void write_glb(const std::string& path, const std::vector<float>& positions, const std::vector<float>& normals,
               const std::vector<uint32_t>& indices) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "stipple tools/make_blobby.cpp";

    tinygltf::Buffer buffer;
    append_bytes(buffer.data, positions);
    append_bytes(buffer.data, normals);
    append_bytes(buffer.data, indices);
    model.buffers.push_back(std::move(buffer));

    auto add_view = [&](size_t offset, size_t length, int target) {
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = length;
        view.target = target;
        model.bufferViews.push_back(view);
        return static_cast<int>(model.bufferViews.size() - 1);
    };
    const size_t vec_bytes = positions.size() * sizeof(float);
    const int position_view = add_view(0, vec_bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int normal_view = add_view(vec_bytes, vec_bytes, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int index_view = add_view(2 * vec_bytes, indices.size() * sizeof(uint32_t),
                                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

    auto add_accessor = [&](int view, int component, int type, size_t count) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.byteOffset = 0;
        accessor.componentType = component;
        accessor.type = type;
        accessor.count = count;
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size() - 1);
    };
    const size_t vertex_count = positions.size() / 3;
    const int position_accessor =
        add_accessor(position_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertex_count);
    // glTF requires min/max on POSITION; computed from the floats actually stored.
    std::vector<double> mn(3, 1e30), mx(3, -1e30);
    for (size_t i = 0; i < positions.size(); ++i) {
        mn[i % 3] = std::min(mn[i % 3], double(positions[i]));
        mx[i % 3] = std::max(mx[i % 3], double(positions[i]));
    }
    model.accessors[position_accessor].minValues = mn;
    model.accessors[position_accessor].maxValues = mx;
    const int normal_accessor =
        add_accessor(normal_view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertex_count);
    const int index_accessor =
        add_accessor(index_view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());

    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = position_accessor;
    primitive.attributes["NORMAL"] = normal_accessor;
    primitive.indices = index_accessor;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "blobby";
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);

    tinygltf::Node node;
    node.name = "blobby";
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    // Serialise to memory and write the file ourselves: tinygltf 2.7's WriteGltfSceneToFile
    // reports success even when the file cannot be opened.
    tinygltf::TinyGLTF writer;
    std::ostringstream glb;
    if (!writer.WriteGltfSceneToStream(&model, glb, /*prettyPrint=*/false, /*writeBinary=*/true))
        stipple::fail_file(path, "cannot serialise glTF");
    const std::string bytes = glb.str();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) stipple::fail_file(path, "cannot open for writing");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) stipple::fail_file(path, "cannot write");
}

int run(const std::string& out_path) {
    Surface s = polygonise();
    relax(s, 12);
    check_closed(s);
    check_orientation(s);
    check_single_sphere(s);
    const double weakest = min_surface_gradient(s);
    STIPPLE_CHECK(weakest > kMinSurfaceGradient, "field gradient too weak on the surface");

    // Vertex cache then fetch order: the asset is what every default render draws, so give the
    // GPU a well-ordered index buffer. Both meshoptimizer passes are deterministic.
    const size_t vertex_count = s.positions.size();
    std::vector<uint32_t> indices(s.indices.size());
    meshopt_optimizeVertexCache(indices.data(), s.indices.data(), s.indices.size(), vertex_count);
    std::vector<float> positions(vertex_count * 3), normals(vertex_count * 3);
    for (size_t v = 0; v < vertex_count; ++v) {
        const dvec3 n = outward_normal(s.positions[v]);
        for (int k = 0; k < 3; ++k) {
            positions[v * 3 + k] = static_cast<float>(s.positions[v][k]);
            normals[v * 3 + k] = static_cast<float>(n[k]);
        }
    }
    std::vector<unsigned int> remap(vertex_count);
    const size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertex_count);
    STIPPLE_CHECK(used == vertex_count, "unreferenced vertex");
    // Separate destinations: the header does not promise that remapping in place is allowed.
    std::vector<uint32_t> final_indices(indices.size());
    std::vector<float> final_positions(positions.size()), final_normals(normals.size());
    meshopt_remapIndexBuffer(final_indices.data(), indices.data(), indices.size(), remap.data());
    meshopt_remapVertexBuffer(final_positions.data(), positions.data(), vertex_count, 3 * sizeof(float), remap.data());
    meshopt_remapVertexBuffer(final_normals.data(), normals.data(), vertex_count, 3 * sizeof(float), remap.data());

    write_glb(out_path, final_positions, final_normals, final_indices);
    std::printf("make_blobby: wrote %s: %zu triangles, %zu vertices (min surface gradient %.3f)\n",
                out_path.c_str(), final_indices.size() / 3, vertex_count, weakest);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const char* usage = "usage: make_blobby OUT.glb\n  writes the default scene's model, a blobby metaball surface like the paper's Figure 1, as glTF\n";
    if (argc == 2 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))) {
        std::printf("%s", usage);
        return 0;
    }
    if (argc != 2 || argv[1][0] == '-') {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    try {
        return run(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_blobby: %s\n", e.what());
        return 1;
    }
}
