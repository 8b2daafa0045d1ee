// Stipple generation speed and quality on UV spheres of ~100k and ~1M triangles (relaxation and
// progressive order included). Prints its figures; the test suite asserts quality, never time.
// Usage: generation_speed [TRIANGLES ...]   (default: 100000 1000000)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/error.hpp"
#include "mesh/primitives.hpp"
#include "stipple/quality.hpp"
#include "stipple/stipple_set.hpp"

int main(int argc, char** argv) {
    using namespace stipple;
    std::vector<size_t> sizes;
    for (int i = 1; i < argc; ++i) sizes.push_back(std::strtoull(argv[i], nullptr, 10));
    if (sizes.empty()) sizes = {100000, 1000000};
    try {
        for (size_t triangles : sizes) {
            const Mesh mesh = make_uv_sphere(triangles);
            const double area = total_area(mesh);
            for (double count : {500000.0, 2000000.0}) {
                GenerationParams params;
                // D_max for `count` stipples on the unit sphere: area * (kReferenceHeight/2)^2 reference px^2.
                params.dmax = float(count / (area * std::pow(kReferenceHeight / 2.0, 2)));
                const StippleSet set = generate_stipples(mesh, params);
                std::printf("%zu triangles, %zu stipples: %.3f s, %.0f stipples/s, delta-bar %.3f (prefix f=0.25: %.3f)\n",
                            mesh.triangle_count(), set.size(), set.generation_seconds,
                            set.size() / set.generation_seconds, normalized_nn_distance(set.positions, area),
                            normalized_nn_distance(prefix_at_fraction(set, 0.25), area));
            }
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "generation_speed: %s\n", e.what());
        return 1;
    }
    return 0;
}
