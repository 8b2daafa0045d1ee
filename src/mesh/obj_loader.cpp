// OBJ, read by a parser of our own. tinyobjloader (used until 2026-12-03) was lenient in ways that hid
// broken files and wrong in ways that changed good ones: it read "nan", "inf" and other non-numbers
// as 0 (a normal "vn nan 1 0" loaded as +Y), cut concave polygons into overlapping triangles (an
// L-shaped face of area 3 loaded as one triangle of area 1; a concave quad was split along its shorter
// diagonal), took quadratic time on large polygons (28 s for one face of 100k corners), allocated
// about 320 KB for every "t" tag line (a 57 KB file took 2.9 GB), and knew no line continuations.
// Here every number is checked where it stands, polygons are cut as the PLY loader cuts them
// (triangulate_polygon), lines other than v, vn and f are skipped, and each problem is one line
// naming the line of the file.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"
#include "mesh/polygon_triangulation.hpp"

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

enum class Number { ok, not_a_number, too_large };

// A decimal number as a float. Magnitudes below float's smallest read as that tiny value or zero (they
// are a model's rounding, 1e-50); above its largest they are refused (too_large).
// too_large sets `value` to the infinity of its sign.
Number parse_float(std::string_view word, float& value);

// A decimal number in double precision, refused (too_large) beyond float's range as parse_float refuses it.
Number parse_coordinate(std::string_view word, double& value) {
    float narrow = 0.0f;
    const Number n = parse_float(word, narrow);
    if (n != Number::ok) {
        value = double(narrow);
        return n;
    }
    if (word.size() > 1 && word.front() == '+') word.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || ptr != word.data() + word.size()) value = double(narrow);  // below double's range: float's reading
    return Number::ok;
}

Number parse_float(std::string_view word, float& value) {
    // from_chars refuses the sign strtod accepts (but "+-5" stays refused).
    if (word.size() > 1 && word.front() == '+' && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.'))
        word.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec == std::errc::result_out_of_range && ptr == word.data() + word.size()) {
        // from_chars says out of range both below and above float's range; strtod tells which.
        const double wide = std::strtod(std::string(word).c_str(), nullptr);
        if (std::abs(wide) >= 1.0) {
            value = std::copysign(std::numeric_limits<float>::infinity(), static_cast<float>(wide));
            return Number::too_large;
        }
        value = static_cast<float>(wide);
        return Number::ok;
    }
    if (ec != std::errc() || ptr != word.data() + word.size()) return Number::not_a_number;
    return Number::ok;
}

class ObjReader {
public:
    ObjReader(const std::string& path, uint64_t limit) : path_(path), limit_(limit) {}

    void read(std::string_view text) {
        if (const size_t zero = text.find('\0'); zero != std::string_view::npos)
            fail_file(path_, "not a text OBJ file (zero byte at offset " + std::to_string(zero) + ")");
        if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte-order mark
        std::string joined;  // a line continued with a backslash, gathered
        size_t pos = 0, physical = 0;
        while (pos < text.size()) {
            // Line ends "\n", "\r\n" or a lone "\r".
            size_t eol = text.find_first_of("\r\n", pos);
            if (eol == std::string_view::npos) eol = text.size();
            std::string_view piece = text.substr(pos, eol - pos);
            pos = eol + (eol + 1 < text.size() && text[eol] == '\r' && text[eol + 1] == '\n' ? 2 : 1);
            // A comment ends the line, a backslash in it included ("# from C:\models\" continues nothing).
            if (const size_t hash = piece.find('#'); hash != std::string_view::npos) piece = piece.substr(0, hash);
            ++physical;
            if (joined.empty()) line_ = physical;
            std::string_view trimmed = piece;
            while (!trimmed.empty() && is_space(trimmed.back())) trimmed.remove_suffix(1);
            if (!trimmed.empty() && trimmed.back() == '\\') {  // continued on the next line
                joined.append(trimmed.substr(0, trimmed.size() - 1)).push_back(' ');
                if (pos < text.size()) continue;
                piece = {};  // the file ends in a continuation: the line ends with it
            }
            if (!joined.empty()) {
                joined.append(piece);
                line(joined);
                joined.clear();
            } else {
                line(piece);
            }
        }
        // Positive indices may refer to vertices defined further down, so they are checked here.
        check_far(far_vertex_, positions_.size(), "vertex", "vertices");
        check_far(far_normal_, normals_.size(), "normal", "normals");
        check_far(far_texcoord_, texcoords_, "texture coordinate", "texture coordinates");
        // A text file of another kind renamed .obj reads as nothing at all (unknown statements are skipped).
        if (face_end_.empty() && positions_.empty())
            fail_file(path_, "no vertex (v) or face (f) statements: not an OBJ model");
        if (face_end_.empty())
            fail_file(path_, "the model has no triangles (" + std::to_string(positions_.size()) + " vertices and no face (f) statements)");
    }

    // Polygons into triangles; where faces give one position different normals, the first normal keeps
    // the position's place and each other (position, normal) pair becomes one extra vertex at the end.
    // Every position of the file keeps its place (unused ones too: the model is what the file lists).
    Mesh mesh() {
        const bool all_normals =
            !normals_.empty() && std::none_of(corner_normal_.begin(), corner_normal_.end(), [](int32_t n) { return n < 0; });
        Mesh mesh;
        mesh.source = path_;
        // In double as read, then about the model's own centre where it lies far from the file's origin: the
        // centre of the vertices the faces use (a vertex left unused at the origin made the model look near it).
        mesh.origin = far_origin(positions_, corner_vertex_);
        mesh.positions.reserve(positions_.size());
        for (const glm::dvec3& p : positions_) mesh.positions.push_back(glm::vec3(p - mesh.origin));
        std::vector<glm::dvec3>().swap(positions_);
        std::vector<int32_t> normal_of;  // the normal index that claimed each position, -1 while unused
        if (all_normals) {
            mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));  // +Z for unused positions
            normal_of.assign(mesh.positions.size(), -1);
        }
        std::unordered_map<uint64_t, uint32_t> extra;
        auto vertex_of = [&](size_t corner) {
            uint32_t v = corner_vertex_[corner];
            if (!all_normals) return v;
            const int32_t n = corner_normal_[corner];
            if (normal_of[v] < 0) {
                normal_of[v] = n;
                mesh.normals[v] = normals_[size_t(n)];
            } else if (normal_of[v] != n) {
                const uint64_t key = (uint64_t(v) << 32) | uint32_t(n);
                const auto [it, added] = extra.try_emplace(key, uint32_t(mesh.positions.size()));
                if (added) {
                    mesh.positions.push_back(mesh.positions[v]);
                    mesh.normals.push_back(normals_[size_t(n)]);
                }
                v = it->second;
            }
            return v;
        };
        size_t triangles = 0;
        for (size_t f = 0, begin = 0; f < face_end_.size(); begin = face_end_[f++]) triangles += face_end_[f] - begin - 2;
        mesh.indices.reserve(3 * triangles);
        // A polygon is cut over its corner slots, so that each corner keeps its own normal.
        std::vector<glm::vec3> polygon;
        std::vector<uint32_t> slots, cut;
        for (size_t f = 0, begin = 0; f < face_end_.size(); begin = face_end_[f++]) {
            const size_t n = face_end_[f] - begin;
            if (n == 3) {
                for (size_t k = 0; k < 3; ++k) mesh.indices.push_back(vertex_of(begin + k));
                continue;
            }
            polygon.resize(n);
            slots.resize(n);
            cut.resize(3 * (n - 2));
            for (size_t k = 0; k < n; ++k) polygon[k] = mesh.positions[corner_vertex_[begin + k]], slots[k] = uint32_t(k);
            if (triangulate_polygon(polygon, slots, cut) == Triangulated::budget_spent)
                fail_file(path_, "face " + std::to_string(f + 1) + ": a concave polygon of " + std::to_string(n) +
                                     " corners is too large to cut into triangles here (split it into smaller faces)");
            for (uint32_t slot : cut) mesh.indices.push_back(vertex_of(begin + slot));
        }
        return mesh;
    }

private:
    struct Far {  // the largest positive index seen, and where
        uint64_t index = 0;
        uint64_t face = 0;
        size_t line = 0;
    };

    std::string at() const { return " (line " + std::to_string(line_) + ")"; }

    // Messages are built only on failure: these run for every vertex and corner of the file.
    std::string vertex_here() const { return "vertex " + std::to_string(positions_.size() + 1) + at(); }
    std::string normal_here() const { return "normal " + std::to_string(normals_.size() + 1) + at(); }
    std::string face_here() const { return "face " + std::to_string(face_end_.size() + 1) + at(); }

    // Comments are already cut off (read): also those after the data ("f 1 2 3 # the lid", as some exporters write).
    void line(std::string_view rest) {
        const std::string_view keyword = next_word(rest);
        if (keyword == "v") vertex(rest);
        else if (keyword == "vn") normal(rest);
        else if (keyword == "f") face(rest);
        else if (keyword == "vt") ++texcoords_;  // counted only: a face's texture index must name one
        // Anything else (o, g, s, usemtl, mtllib, l, p, t, comments, ...) plays no part in stippling.
    }

    void within_limit(uint64_t count, const char* what) const {
        if (count >= limit_)
            fail_file(path_, "has more than " + std::to_string(limit_) + " " + what + ", the limit");
    }

    void vertex(std::string_view rest) {
        within_limit(positions_.size(), "vertices");
        glm::dvec3 p;
        for (int axis = 0; axis < 3; ++axis) {
            const std::string_view word = next_word(rest);
            if (word.empty()) fail_file(path_, vertex_here() + " has fewer than 3 coordinates");
            switch (parse_coordinate(word, p[axis])) {
                case Number::ok: break;
                case Number::not_a_number: fail_file(path_, vertex_here() + ": " + shown(word) + " is not a number");
                case Number::too_large:
                    fail_file(path_, vertex_here() + " has an infinite coordinate (" + shown(word) + " is beyond float range)");
            }
            if (std::isnan(p[axis])) fail_file(path_, vertex_here() + " has a NaN coordinate");
            if (std::isinf(p[axis])) fail_file(path_, vertex_here() + " has an infinite coordinate");
        }
        positions_.push_back(p);  // a fourth value (w) or a colour after the three is left
    }

    // A normal that is not finite (NaN, or beyond float range: infinite) is kept as read: the loader then
    // computes every normal (load_mesh.cpp).
    void normal(std::string_view rest) {
        within_limit(normals_.size(), "normals");
        glm::vec3 n;
        for (int axis = 0; axis < 3; ++axis) {
            const std::string_view word = next_word(rest);
            if (word.empty()) fail_file(path_, normal_here() + " has fewer than 3 components");
            if (parse_float(word, n[axis]) == Number::not_a_number)
                fail_file(path_, normal_here() + ": " + shown(word) + " is not a number");
        }
        normals_.push_back(n);
    }

    void face(std::string_view rest) {
        within_limit(face_end_.size(), "faces");
        const size_t begin = corner_vertex_.size();
        for (std::string_view word = next_word(rest); !word.empty(); word = next_word(rest)) {
            within_limit(corner_vertex_.size(), "face corners");
            const size_t slash = word.find('/');
            corner_vertex_.push_back(index(word.substr(0, slash), positions_.size(), far_vertex_, "vertex", "vertices"));
            const size_t slash2 = slash == std::string_view::npos ? slash : word.find('/', slash + 1);
            // Texture coordinates play no part, but an index beyond them is a broken file all the same.
            if (slash != std::string_view::npos) {
                const std::string_view texture =
                    word.substr(slash + 1, slash2 == std::string_view::npos ? std::string_view::npos : slash2 - slash - 1);
                if (!texture.empty()) index(texture, texcoords_, far_texcoord_, "texture coordinate", "texture coordinates");
            }
            corner_normal_.push_back(slash2 == std::string_view::npos
                                         ? -1
                                         : int32_t(index(word.substr(slash2 + 1), normals_.size(), far_normal_, "normal", "normals")));
        }
        const size_t corners = corner_vertex_.size() - begin;
        if (corners < 3)
            fail_file(path_, face_here() + " has " + std::to_string(corners) + " vertices; a face needs at least 3");
        face_end_.push_back(corner_vertex_.size());
    }

    // The 0-based index an OBJ index (1-based, or negative: counted back from the last one defined) names.
    uint32_t index(std::string_view word, uint64_t defined, Far& far, const char* what, const char* whats) {
        int64_t value = 0;
        const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ec != std::errc() || ptr != word.data() + word.size())
            fail_file(path_, face_here() + ": " + shown(word) + " is not a " + what + " index");
        if (value == 0) fail_file(path_, face_here() + " uses " + what + " index 0 (OBJ indices start at 1)");
        if (value < 0) {
            if (uint64_t(-(value + 1)) >= defined)  // -(value + 1): INT64_MIN has no positive counterpart
                fail_file(path_, face_here() + " refers to " + what + " " + std::to_string(value) + " but only " +
                                     std::to_string(defined) + " " + whats + " come before it");
            return uint32_t(int64_t(defined) + value);
        }
        // Checked once the file is read (it may name a vertex defined further down); beyond the limit now.
        if (uint64_t(value) > far.index) far = Far{uint64_t(value), face_end_.size() + 1, line_};
        if (uint64_t(value) > limit_) check_far(far, defined, what, whats);
        return uint32_t(value - 1);
    }

    void check_far(const Far& far, uint64_t defined, const char* what, const char* whats) const {
        if (far.index > defined)
            fail_file(path_, "face " + std::to_string(far.face) + " (line " + std::to_string(far.line) + ") refers to " +
                                 what + " " + std::to_string(far.index) + " but there are only " +
                                 std::to_string(defined) + " " + whats);
    }

    const std::string& path_;
    uint64_t limit_;
    size_t line_ = 0;  // the (first) line of the line being read
    std::vector<glm::dvec3> positions_;  // as read, in double: a model far from its origin keeps its shape
    std::vector<glm::vec3> normals_;
    std::vector<uint32_t> corner_vertex_;  // 0-based, by corner, faces one after another
    std::vector<int32_t> corner_normal_;   // 0-based, -1 where the corner names none
    std::vector<size_t> face_end_;         // each face's end in the corner lists
    uint64_t texcoords_ = 0;               // vt lines: counted, not kept
    Far far_vertex_, far_normal_, far_texcoord_;
};

}  // namespace

Mesh parse_obj(const std::string& path, std::string_view text, const LoadOptions& options) {
    // Indices are stored in 32 bits (and corners counted as int32 normals): the limit keeps them there.
    ObjReader reader(path, std::min<uint64_t>(options.max_elements, std::numeric_limits<int32_t>::max()));
    reader.read(text);
    return reader.mesh();
}

}  // namespace stipple
