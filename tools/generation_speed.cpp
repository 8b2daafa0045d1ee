// Stipple generation speed and quality on UV spheres of ~100k and ~1M triangles and on a 12-triangle
// cube, whose few large triangles hold ~10^5 stipples each (relaxation and progressive order
// included), with delta-bar and, on a face of the cube, the six-fold order psi_6 (quality.hpp). Prints
// its figures; the test suite asserts quality, never time. Each line ends with what opening a model adds to
// generation: the polygons' selection ranking (it grows with the triangles, and more with those that hold a
// candidate) and the stipples' round trip through their stored coordinates.
// `pile`: a grid beside 3,000 copies of one small triangle (a broken model's piled faces), whose stipples
// crowd one place: it checks that generation stays linear there (relax.cpp kMaxNeighbours,
// progressive_order.cpp kMaxPushed; 80 s for 330k stipples before those).
// Usage: generation_speed [TRIANGLES | cube | pile ...]   (default: 100000 1000000 cube)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/primitives.hpp"
#include "stipple/quality.hpp"
#include "stipple/stipple_cache.hpp"
#include "stipple/stipple_set.hpp"

namespace {

// The cube of side 2 around the origin, two triangles per face.
stipple::Mesh make_cube() {
    stipple::Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back({i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f});
    const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) mesh.indices.insert(mesh.indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    mesh.source = "cube";
    return mesh;
}

// A 64x64 grid and, above it, 3,000 copies of one triangle of 1/40 of its side (about half the area).
stipple::Mesh make_pile() {
    stipple::Mesh mesh = stipple::make_grid(64);
    const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{0.0f, 0.0f, 0.5f}, {0.05f, 0.0f, 0.5f}, {0.0f, 0.05f, 0.5f}});
    for (int copy = 0; copy < 3000; ++copy) mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    stipple::compute_vertex_normals(mesh);
    mesh.source = "pile";
    return mesh;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace stipple;
    std::vector<std::string> meshes;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool count = !arg.empty() && arg.size() <= 9 && arg.find_first_not_of("0123456789") == std::string::npos;
        if (arg != "cube" && arg != "pile" && (!count || std::stoull(arg) < 8)) {
            std::fprintf(stderr, "usage: generation_speed [TRIANGLES (>= 8) | cube | pile ...]  (default: 100000 1000000 cube)\n");
            return arg == "--help" || arg == "-h" ? 0 : 2;
        }
        meshes.push_back(arg);
    }
    if (meshes.empty()) meshes = {"100000", "1000000", "cube"};
    try {
        for (const std::string& name : meshes) {
            const Mesh mesh = name == "cube"   ? make_cube()
                              : name == "pile" ? make_pile()
                                               : make_uv_sphere(std::strtoull(name.c_str(), nullptr, 10));
            const double area = total_area(mesh);
            for (double count : {500000.0, 2000000.0}) {
                GenerationParams params;
                // D_max for `count` stipples: reference px^2 = area * px_per_unit^2, where the bounding
                // sphere's radius spans kReferenceHeight / 2 px.
                const double radius = compute_bounding_sphere(mesh).radius;
                params.dmax = float(count / (area * std::pow(kReferenceHeight / 2.0 / radius, 2)));
                StippleSet set = generate_stipples(mesh, params);  // finished in place after its figures
                std::printf("%s: %zu triangles, %zu stipples: %.3f s, %.0f stipples/s",
                            name == "cube" ? "cube" : name == "pile" ? "grid and pile" : "UV sphere", mesh.triangle_count(),
                            set.size(), set.generation_seconds, set.size() / set.generation_seconds);
                // The pile has no spread to speak of, and the metric's neighbour search is as crowded there.
                if (name != "pile")
                    std::printf(", delta-bar %.3f (prefix f=0.25: %.3f)", normalized_nn_distance(set.positions, area),
                                normalized_nn_distance(prefix_at_fraction(set, 0.25), area));
                if (name == "cube") {  // hexagonal regularity on one face (quality.hpp)
                    std::vector<glm::vec3> face;
                    for (const glm::vec3& p : set.positions)
                        if (p.z > 0.9999f) face.push_back(p);
                    const HexagonalOrder order = hexagonal_order(face, {0, 0, 1});
                    std::printf(", psi_6 on a face: local %.3f, windowed %.3f", order.local, order.windowed);
                }
                // What opening a model waits for besides: the polygons' selection ranking (§2.3) and the
                // round trip through the stored coordinates, which `stipple info` and the bench count in their
                // generation time. The ranking is per triangle: on fine meshes it takes longer than generating.
                const auto start = std::chrono::steady_clock::now();
                finish_generated_stipples(mesh, params.seed, set);
                const double ranking = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::printf("; with the polygons' ranking and the stored coordinates %.3f s more: %.0f stipples/s\n", ranking,
                            set.size() / (set.generation_seconds + ranking));
            }
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "generation_speed: %s\n", e.what());
        return 1;
    }
    return 0;
}
