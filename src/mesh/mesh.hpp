#pragma once
// The one in-memory form of every model: an indexed triangle list in object space.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace stipple {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    // Corner i of 8: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
    glm::vec3 corner(int i) const { return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z}; }
};

// Bounding sphere used for framing, silhouette thinning (paper §3.1) and the reference scale
// of stipple generation.
struct Sphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

// What loading did to the file's winding (orient_consistently, mesh/orientation.hpp), for `stipple info`.
struct WindingRepair {
    size_t parts = 0;                 // sets of triangles joined through manifold edges
    size_t triangles_turned = 0;      // triangles whose corner order was reversed, for either reason:
    size_t wound_against = 0;         // triangles wound against their part's majority
    size_t parts_turned_outward = 0;  // parts that were clearly inside out once wound alike
    size_t parts_turned_to_normals = 0;  // of those, open parts turned to agree with the file's normals
    size_t conflicting_edges = 0;     // manifold edges still joining two triangles wound the same way
                                      // (a part that has no consistent winding, such as a Möbius strip)
    size_t normals_turned = 0;        // file normals turned to agree with their faces
    size_t border_edges = 0;          // edges of one triangle (holes' rims, a sheet's edges): the surface is open
};

struct Mesh {
    std::string source;                // path it was loaded from (for messages), or a generator name
    std::vector<glm::vec3> positions;  // one per vertex, finite
    std::vector<glm::vec3> normals;    // one per vertex, unit length (computed when the file has none)
    std::vector<uint32_t> indices;     // 3 per triangle, each < positions.size()
    // Where the file puts the stored (0, 0, 0): a model far from its file's origin is stored about the centre of
    // its box (far_origin), so that single precision keeps its shape; the drawing puts it back (object_to_world).
    glm::dvec3 origin{0.0};
    WindingRepair winding;             // set by load_mesh
    size_t duplicates_dropped = 0;     // set by load_mesh (drop_duplicate_triangles: repeats, and two corners at one place)
    bool normals_computed = false;     // a reader computed some normals (a glTF primitive without them): not the file's
    std::string decoded;               // set by the glTF loader: the storage extensions it decoded, for `info`

    size_t triangle_count() const { return indices.size() / 3; }
    size_t vertex_count() const { return positions.size(); }
};

// Area-weighted vertex normals from the faces; degenerate faces contribute nothing and a
// vertex with no usable face gets +Z so that every normal is unit length.
void compute_vertex_normals(Mesh& mesh);

// The coordinates a model may have. Rendering works in single precision and multiplies coordinates
// together (squared lengths, areas): beyond 1e18 those overflow, and below an extent of 1e-15 they fall
// among the denormals (2026-11-28: a triangle drew the same from 1e-18 to 1e18 units across; at 1e19
// nothing, at 1e-20 twice its stipples).
inline constexpr float kMaxCoordinate = 1e18f;
inline constexpr float kMinExtent = 1e-15f;
// Far from the origin a float keeps about 1.7e7 steps of its magnitude: at 1e5 times its size a model is
// drawn with ~170 steps across (the shared spot moved 1e7 units away collapsed to a few points and drew
// nothing).
inline constexpr float kMaxOffsetOverExtent = 1e5f;
// A model read in double precision (OBJ) whose box's centre lies farther than this many times its extent from
// the file's origin is stored about that centre (Mesh::origin): at 1e4 times its size a sphere's stipples fell
// on a lattice of float steps and its tone fell by a tenth, at 1e5 by half. Below it single precision keeps its
// shape to 1e-5 of its size, and models near their origin keep their coordinates (and their stipples) exactly.
inline constexpr double kRecentreOverExtent = 100.0;
// The origin to store `positions` about (kRecentreOverExtent), or 0 where they are near their own; 0 too where a
// coordinate lies beyond kMaxCoordinate (validate_mesh refuses the model).
glm::dvec3 far_origin(std::span<const glm::dvec3> positions);
// far_origin of the vertices `indices` use (a vertex left unused at the file's origin made a far model look
// near it; indices beyond `positions` are skipped, validate_mesh reports them).
glm::dvec3 far_origin(std::span<const glm::dvec3> positions, std::span<const uint32_t> indices);
// Sets mesh.origin to far_origin(exact, mesh.indices) and, where it is not 0, mesh.positions to `exact` about it:
// a reader that read the positions in more than single precision (one per mesh vertex) keeps a far model's shape.
void store_about_far_origin(Mesh& mesh, std::span<const glm::dvec3> exact);

// Throws stipple::Error("<source>: ...") if an index is out of range, a coordinate is NaN/Inf or beyond
// kMaxCoordinate, the model is less than kMinExtent across or lies beyond kMaxOffsetOverExtent times its size
// from the origin,
// the index count is not a multiple of 3, normals are missing/mismatched, or there is no triangle.
void validate_mesh(const Mesh& mesh);

Bounds compute_bounds(const Mesh& mesh);
// The mesh reflected through its origin (every position and normal negated) and re-wound, so that its faces
// still face out: a mirroring scene transform draws this with a proper matrix (Transform::drawing_matrix).
Mesh reflected_through_origin(const Mesh& mesh);
Sphere compute_bounding_sphere(const Mesh& mesh);  // Ritter-style, contains every vertex
// A sphere holding what `sphere` and `box` (two bounds of the same points) hold, after `model` (a similarity
// or not): the sphere's image, its radius stretched by the model's largest stretch, and where the model
// stretches some directions more than others (a scene matrix exaggerating a terrain's heights) the sphere
// around the box's corners instead when that is smaller (a flat object's sphere stretched along its thin
// axis was as wide as the whole stretch).
Sphere transformed_bounds(const Sphere& sphere, const Bounds& box, const glm::mat4& model);
// The same bound's radius about the image of sphere.center (the centre the drawing measures depth and size
// from): the sphere's radius times the model's largest stretch, or the farthest image of the box's corners
// from that centre where smaller.
float transformed_radius(const Sphere& sphere, const Bounds& box, const glm::mat4& model);
double triangle_area(const Mesh& mesh, size_t triangle);
double total_area(const Mesh& mesh);

// Reorders triangles for vertex reuse and vertices for fetch locality (meshoptimizer). The same
// surface, drawn in an order that suits a rasteriser's vertex cache; on lavapipe it also groups
// neighbouring triangles, which the compute splat's SIMD lanes and loads like (bunny frame 29 -> 20 ms).
// Deterministic.
void optimize_draw_order(Mesh& mesh);

// Appends b to a (for scenes and multi-primitive files).
void append_mesh(Mesh& a, const Mesh& b);

}  // namespace stipple
