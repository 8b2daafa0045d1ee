// STL, binary and ASCII: what CAD programs and 3D-printing tools export. A list of facets, each with its
// own three corners and a normal. The corners are kept as the file lists them (three vertices a facet, no
// index of shared ones): the format has no smooth normals, and welding the corners of a part's faces would
// average the normals across its sharp edges (a box's faces shaded as if rounded). Loading then computes
// each vertex's normal from its facet (the file's normals, often zero or stale, are not read), and winds and
// repairs the facets as it does every format (load_mesh's finish). Each problem is one line naming the
// facet, or the line of an ASCII file.
//
// Binary: an 80-byte header, a 32-bit little-endian facet count, then 50 bytes a facet (normal and three
// corners as 32-bit floats, and a 16-bit attribute). ASCII: "solid NAME", then for each facet "facet normal
// x y z", "outer loop", three "vertex x y z", "endloop", "endfacet", and "endsolid NAME". A file is binary
// when its size is the size its count announces (a binary header may begin with "solid" too), ASCII when it
// begins with "solid", binary again when its count is 0 and its size holds whole facets or when less than a
// facet of padding follows its counted facets, and neither otherwise.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"

namespace stipple {

namespace {

constexpr size_t kHeaderBytes = 84, kFacetBytes = 50;

// A 32-bit little-endian word: the facet count, and the bits of each float.
uint32_t read_u32(const char* at) {
    return uint32_t(uint8_t(at[0])) | uint32_t(uint8_t(at[1])) << 8 | uint32_t(uint8_t(at[2])) << 16 |
           uint32_t(uint8_t(at[3])) << 24;
}

float read_float(const char* at) {
    const uint32_t bits = read_u32(at);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

void add_corner(Mesh& mesh, const glm::vec3& p) {
    mesh.indices.push_back(uint32_t(mesh.positions.size()));
    mesh.positions.push_back(p);
}

Mesh parse_binary(const std::string& name, std::string_view bytes, uint64_t facets, const LoadOptions& options) {
    if (facets == 0) fail_file(name, "the model has no triangles (a binary STL of 0 facets)");
    if (facets > options.max_elements)
        fail_file(name, "binary STL announces " + std::to_string(facets) + " facets, more than the limit of " +
                            std::to_string(options.max_elements));
    Mesh mesh;
    mesh.positions.reserve(3 * facets);
    mesh.indices.reserve(3 * facets);
    for (uint64_t f = 0; f < facets; ++f) {
        const char* facet = bytes.data() + kHeaderBytes + f * kFacetBytes;
        for (int corner = 0; corner < 3; ++corner) {
            const char* at = facet + 12 + 12 * corner;  // after the facet's normal
            const glm::vec3 p(read_float(at), read_float(at + 4), read_float(at + 8));
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                fail_file(name, "facet " + std::to_string(f) + " has a corner that is not a finite number");
            add_corner(mesh, p);
        }
    }
    return mesh;
}

class AsciiReader {
public:
    AsciiReader(const std::string& name, std::string_view text, const LoadOptions& options)
        : name_(name), text_(text), limit_(options.max_elements) {}

    Mesh read() {
        expect("solid");
        skip_line();  // the solid's name, if any
        for (;;) {
            const std::string_view word = next();
            if (word.empty()) fail_here("the file ends before \"endsolid\"");
            if (is(word, "endsolid")) {
                skip_line();
                // Several solids may follow one another; anything else after the last one is refused.
                const std::string_view after = next();
                if (after.empty()) break;
                if (!is(after, "solid")) fail_here("expected \"solid\" or the end of the file after \"endsolid\", got " + shown(after));
                skip_line();
                continue;
            }
            if (!is(word, "facet")) fail_here("expected \"facet\" or \"endsolid\", got " + shown(word));
            expect("normal");
            // The file's normal is not used (see the top of this file), so not checked either: exporters write
            // "nan" or "inf" there for degenerate facets.
            for (int i = 0; i < 3; ++i)
                if (next().empty()) fail_here("the file ends where a facet's normal was expected");
            expect("outer");
            expect("loop");
            for (int corner = 0; corner < 3; ++corner) {
                expect("vertex");
                glm::dvec3 p;
                for (int i = 0; i < 3; ++i) p[i] = number();
                exact_.push_back(p);
                add_corner(mesh_, glm::vec3(p));
            }
            expect("endloop");
            expect("endfacet");
            if (mesh_.triangle_count() > limit_)
                fail_file(name_, "more than " + std::to_string(limit_) + " facets, the limit");
        }
        if (mesh_.indices.empty()) fail_file(name_, "the model has no triangles (an ASCII STL without facets)");
        // Far from the file's origin, about the model's own centre (Mesh::origin, as the OBJ and PLY readers
        // keep it): the text holds more than single precision (a unit sphere 90,000 units out lost its shape).
        store_about_far_origin(mesh_, exact_);
        return std::move(mesh_);
    }

private:
    static std::string shown(std::string_view word) {
        std::string out = "'";
        for (char c : word.substr(0, 24)) out += c >= 0x20 && c < 0x7f ? c : '?';
        return out + (word.size() > 24 ? "...'" : "'");
    }

    [[noreturn]] void fail_here(const std::string& problem) const {
        fail_file(name_, "line " + std::to_string(line_) + ": " + problem);
    }

    // The next word, or an empty view at the end of the file; counts lines on the way.
    std::string_view next() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            // Lines end in "\n", "\r\n" or a lone "\r".
            if (text_[pos_] == '\n' || (text_[pos_] == '\r' && (pos_ + 1 == text_.size() || text_[pos_ + 1] != '\n'))) ++line_;
            ++pos_;
        }
        const size_t begin = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        return text_.substr(begin, pos_ - begin);
    }

    // The rest of a "solid" or "endsolid" line: its name. A writer that puts a whole file on one line leaves no
    // line end: the name is then the words before the first "facet" (or "endsolid").
    void skip_line() {
        for (;;) {
            // Every space but a line end (a vertical tab or form feed read as a word of no letters looped for ever).
            while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r' &&
                   std::isspace(static_cast<unsigned char>(text_[pos_])))
                ++pos_;
            if (pos_ >= text_.size() || text_[pos_] == '\n' || text_[pos_] == '\r') return;
            const size_t word = pos_;
            while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
            const std::string_view w = text_.substr(word, pos_ - word);
            if (is(w, "facet") || is(w, "endsolid")) {
                pos_ = word;
                return;
            }
        }
    }

    // Keywords in any case: the format's are lower case, but some writers use upper case.
    static bool is(std::string_view word, std::string_view keyword) {
        if (word.size() != keyword.size()) return false;
        for (size_t i = 0; i < word.size(); ++i)
            if (std::tolower(static_cast<unsigned char>(word[i])) != keyword[i]) return false;
        return true;
    }

    void expect(std::string_view keyword) {
        const std::string_view word = next();
        if (word.empty()) fail_here("the file ends where \"" + std::string(keyword) + "\" was expected");
        if (!is(word, keyword)) fail_here("expected \"" + std::string(keyword) + "\", got " + shown(word));
    }

    // In double, as written (the model may lie far from the file's origin: read()).
    double number() {
        std::string_view word = next();
        if (word.empty()) fail_here("the file ends where a number was expected");
        if (word.size() > 1 && word.front() == '+' && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.'))
            word.remove_prefix(1);
        double value = 0.0;
        const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ptr != word.data() + word.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
            fail_here("expected a number, got " + shown(word));
        // Out of range: below it, a rounding to keep (1e-400 is 0); above it, refused.
        if (ec == std::errc::result_out_of_range) {
            const double wide = std::strtod(std::string(word).c_str(), nullptr);
            if (std::abs(wide) >= 1.0) fail_here("the number " + shown(word) + " is beyond single precision's range");
            value = wide;
        }
        if (!std::isfinite(value)) fail_here("the number " + shown(word) + " is not finite");
        if (!std::isfinite(float(value))) fail_here("the number " + shown(word) + " is beyond single precision's range");
        return value;
    }

    const std::string& name_;
    std::string_view text_;
    std::vector<glm::dvec3> exact_;  // the corners as written, for a far origin
    uint64_t limit_;
    size_t pos_ = 0, line_ = 1;
    Mesh mesh_;
};

}  // namespace

Mesh parse_stl(const std::string& name, std::string_view bytes, const LoadOptions& options) {
    if (bytes.size() >= kHeaderBytes) {
        const uint64_t facets = read_u32(bytes.data() + 80);
        if (bytes.size() == kHeaderBytes + facets * kFacetBytes) return parse_binary(name, bytes, facets, options);
    }
    std::string_view text = bytes;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte-order mark
    size_t start = 0;
    while (start < text.size() && std::isspace(static_cast<unsigned char>(text[start]))) ++start;
    std::string first(text.substr(start, 5));
    for (char& c : first) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (first == "solid" && text.find('\0') == std::string_view::npos) return AsciiReader(name, text, options).read();
    if (bytes.size() < kHeaderBytes)
        fail_file(name, "not an STL file: " + std::to_string(bytes.size()) + " bytes, shorter than a binary STL's 84-byte header" +
                            (first == "solid" ? std::string(" and not ASCII text (it holds a zero byte)") : std::string(", and no ASCII \"solid\"")));
    const uint64_t facets = read_u32(bytes.data() + 80);
    // What other readers take too: a count of 0 from a writer that streamed its facets (the facets the size
    // holds), and a few bytes of padding after the last facet (less than a facet: a whole one more would mean
    // the count is wrong).
    const uint64_t data = bytes.size() - kHeaderBytes;
    if (facets == 0 && data > 0 && data % kFacetBytes == 0) return parse_binary(name, bytes, data / kFacetBytes, options);
    if (facets > 0 && data > facets * kFacetBytes && data - facets * kFacetBytes < kFacetBytes)
        return parse_binary(name, bytes, facets, options);
    fail_file(name, "binary STL of " + std::to_string(bytes.size()) + " bytes, where its count of " + std::to_string(facets) +
                        " facets asks " + std::to_string(kHeaderBytes + facets * kFacetBytes) +
                        " (truncated, or not an STL file)");
}

}  // namespace stipple
