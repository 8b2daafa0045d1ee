// OBJ through tinyobjloader, behind a validating pre-scan of our own. tinyobjloader is lenient in
// ways that hide broken files: it reads "nan", "inf" and other non-numbers as 0, silently drops
// quads whose indices are out of range and only warns about other out-of-range indices. The
// pre-scan rejects all of those with the line they are on, before tinyobjloader allocates anything.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

// File text quoted in a message: short, and with no byte that could break the one-line message.
std::string shown(std::string_view text) {
    std::string out = "'";
    for (char c : text.substr(0, 24)) out += c >= 0x20 && c < 0x7f ? c : '?';
    return out + (text.size() > 24 ? "...'" : "'");
}

bool is_space(char c) { return c == ' ' || c == '\t'; }

std::string_view next_word(std::string_view& rest) {
    size_t i = 0;
    while (i < rest.size() && is_space(rest[i])) ++i;
    size_t j = i;
    while (j < rest.size() && !is_space(rest[j])) ++j;
    const std::string_view word = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return word;
}

struct Counts {
    uint64_t vertices = 0;
    uint64_t normals = 0;
    uint64_t faces = 0;
};

class Prescan {
public:
    explicit Prescan(const std::string& path) : path_(path) {}

    Counts run(std::string_view text) {
        if (const size_t zero = text.find('\0'); zero != std::string_view::npos)
            fail_file(path_, "not a text OBJ file (zero byte at offset " + std::to_string(zero) + ")");
        size_t pos = 0;
        while (pos < text.size()) {
            // Line ends as tinyobjloader sees them: "\n", "\r\n" or a lone "\r".
            size_t eol = text.find_first_of("\r\n", pos);
            if (eol == std::string_view::npos) eol = text.size();
            std::string_view rest = text.substr(pos, eol - pos);
            pos = eol + (eol + 1 < text.size() && text[eol] == '\r' && text[eol + 1] == '\n' ? 2 : 1);
            ++line_;
            const std::string_view keyword = next_word(rest);
            if (keyword == "v") vertex(rest);
            else if (keyword == "vn") ++counts_.normals;
            else if (keyword == "f") face(rest);
        }
        // Positive indices may refer to vertices defined further down, so they are checked here.
        check_far(far_vertex_, counts_.vertices, "vertex", "vertices");
        check_far(far_normal_, counts_.normals, "normal", "normals");
        return counts_;
    }

private:
    struct Far {  // the largest positive index seen, and where
        int64_t index = 0;
        uint64_t face = 0;
        size_t line = 0;
    };

    std::string at() const { return " (line " + std::to_string(line_) + ")"; }

    // Messages are built only on failure: these run for every vertex and corner of the file.
    std::string vertex_here() const { return "vertex " + std::to_string(counts_.vertices) + at(); }
    std::string face_here() const { return "face " + std::to_string(counts_.faces) + at(); }

    void vertex(std::string_view rest) {
        ++counts_.vertices;
        for (int axis = 0; axis < 3; ++axis) {
            std::string_view word = next_word(rest);
            if (word.empty()) fail_file(path_, vertex_here() + " has fewer than 3 coordinates");
            if (word.front() == '+') word.remove_prefix(1);  // from_chars refuses the sign strtod accepts
            float value = 0.0f;
            const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
            if (ec == std::errc::result_out_of_range)
                fail_file(path_, vertex_here() + " has an infinite coordinate (" + shown(word) + " is beyond float range)");
            if (ec != std::errc() || ptr != word.data() + word.size())
                fail_file(path_, vertex_here() + ": " + shown(word) + " is not a number");
            if (std::isnan(value)) fail_file(path_, vertex_here() + " has a NaN coordinate");
            if (std::isinf(value)) fail_file(path_, vertex_here() + " has an infinite coordinate");
        }
    }

    void face(std::string_view rest) {
        ++counts_.faces;
        int corners = 0;
        for (std::string_view word = next_word(rest); !word.empty(); word = next_word(rest), ++corners) {
            const size_t slash = word.find('/');
            index(word.substr(0, slash), counts_.vertices, far_vertex_, "vertex", "vertices");
            if (slash == std::string_view::npos) continue;
            const size_t slash2 = word.find('/', slash + 1);
            if (slash2 != std::string_view::npos)
                index(word.substr(slash2 + 1), counts_.normals, far_normal_, "normal", "normals");
        }
        if (corners < 3)
            fail_file(path_, face_here() + " has " + std::to_string(corners) + " vertices; a face needs at least 3");
    }

    void index(std::string_view word, uint64_t defined, Far& far, const char* what, const char* whats) {
        int64_t value = 0;
        const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ec != std::errc() || ptr != word.data() + word.size())
            fail_file(path_, face_here() + ": " + shown(word) + " is not a " + what + " index");
        if (value == 0) fail_file(path_, face_here() + " uses " + what + " index 0 (OBJ indices start at 1)");
        if (value < 0 && static_cast<uint64_t>(-value) > defined)
            fail_file(path_, face_here() + " refers to " + what + " " + std::to_string(value) + " but only " +
                                 std::to_string(defined) + " " + whats + " come before it");
        if (value > far.index) far = Far{value, counts_.faces, line_};
    }

    void check_far(const Far& far, uint64_t defined, const char* what, const char* whats) const {
        if (far.index > 0 && static_cast<uint64_t>(far.index) > defined)
            fail_file(path_, "face " + std::to_string(far.face) + " (line " + std::to_string(far.line) + ") refers to " +
                                 what + " " + std::to_string(far.index) + " but there are only " +
                                 std::to_string(defined) + " " + whats);
    }

    const std::string& path_;
    Counts counts_;
    size_t line_ = 0;
    Far far_vertex_, far_normal_;
};

}  // namespace

Mesh parse_obj(const std::string& path, std::string_view text, const LoadOptions& options) {
    const Counts counts = Prescan(path).run(text);
    // tinyobjloader indexes with int; the limit keeps its allocations bounded as well.
    const uint64_t limit = std::min<uint64_t>(options.max_elements, std::numeric_limits<int32_t>::max());
    for (const auto& [count, what] : {std::pair{counts.vertices, "vertices"}, {counts.normals, "normals"}, {counts.faces, "faces"}})
        if (count > limit)
            fail_file(path, "has " + std::to_string(count) + " " + what + ", more than the limit of " + std::to_string(limit));
    if (counts.faces == 0) fail_file(path, "the model has no triangles");

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    std::istringstream in{std::string(text)};
    // No material reader: materials play no part in stippling, and a missing .mtl must not matter.
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr, /*triangulate=*/true);
    if (!ok || !err.empty()) fail_file(path, one_line(err.empty() ? warn : err));

    const size_t vertex_count = attrib.vertices.size() / 3;
    const size_t normal_count = attrib.normals.size() / 3;
    bool all_normals = normal_count > 0;
    size_t corner_count = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        corner_count += shape.mesh.indices.size();
        for (const tinyobj::index_t& i : shape.mesh.indices) all_normals = all_normals && i.normal_index >= 0;
    }

    // Every position of the file keeps its place (also unused ones: the model is what the file
    // lists). Where faces give one position different normals, the first normal keeps the place
    // and each other (position, normal) pair becomes one extra vertex at the end.
    Mesh mesh;
    mesh.source = path;
    mesh.positions.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v)
        mesh.positions[v] = {attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]};
    std::vector<int> normal_of;  // the normal index that claimed each position, -1 while unused
    if (all_normals) {
        mesh.normals.assign(vertex_count, glm::vec3(0.0f, 0.0f, 1.0f));  // +Z for unused positions
        normal_of.assign(vertex_count, -1);
    }
    std::unordered_map<uint64_t, uint32_t> extra;
    mesh.indices.reserve(corner_count);
    for (const tinyobj::shape_t& shape : shapes) {
        for (size_t k = 0; k < shape.mesh.indices.size(); ++k) {
            const tinyobj::index_t& i = shape.mesh.indices[k];
            // The pre-scan already refused bad indices; this guards against the two disagreeing.
            if (i.vertex_index < 0 || static_cast<size_t>(i.vertex_index) >= vertex_count ||
                (all_normals && static_cast<size_t>(i.normal_index) >= normal_count))
                fail_file(path, "face " + std::to_string(k / 3) + " of shape '" + one_line(shape.name) + "' has an index out of range");
            uint32_t v = static_cast<uint32_t>(i.vertex_index);
            if (all_normals) {
                const float* n = &attrib.normals[3 * static_cast<size_t>(i.normal_index)];
                if (normal_of[v] < 0) {
                    normal_of[v] = i.normal_index;
                    mesh.normals[v] = {n[0], n[1], n[2]};
                } else if (normal_of[v] != i.normal_index) {
                    const uint64_t key = (static_cast<uint64_t>(v) << 32) | static_cast<uint32_t>(i.normal_index);
                    const auto [it, added] = extra.try_emplace(key, static_cast<uint32_t>(mesh.positions.size()));
                    if (added) {
                        mesh.positions.push_back(mesh.positions[v]);
                        mesh.normals.emplace_back(n[0], n[1], n[2]);
                    }
                    v = it->second;
                }
            }
            mesh.indices.push_back(v);
        }
    }
    if (mesh.indices.empty()) fail_file(path, "the model has no triangles");
    return mesh;
}

}  // namespace stipple
