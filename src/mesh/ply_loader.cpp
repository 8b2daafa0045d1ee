// PLY reader of our own: ASCII and both binary byte orders, read from one in-memory copy of the
// file. Every count in the header is checked against the file size and LoadOptions::max_elements
// before anything is allocated, and every read is bounds-checked, so no file can crash, hang or
// exhaust memory.
#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/loader_util.hpp"
#include "mesh/polygon_triangulation.hpp"

namespace stipple {

namespace {

enum class Scalar : uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };

size_t scalar_size(Scalar t) {
    switch (t) {
        case Scalar::i8: case Scalar::u8: return 1;
        case Scalar::i16: case Scalar::u16: return 2;
        case Scalar::i32: case Scalar::u32: case Scalar::f32: return 4;
        case Scalar::f64: return 8;
    }
    return 0;
}

bool is_integer(Scalar t) { return t != Scalar::f32 && t != Scalar::f64; }

bool parse_scalar(std::string_view name, Scalar& out) {
    static constexpr struct { std::string_view name; Scalar type; } names[] = {
        {"char", Scalar::i8},    {"int8", Scalar::i8},     {"uchar", Scalar::u8},   {"uint8", Scalar::u8},
        {"short", Scalar::i16},  {"int16", Scalar::i16},   {"ushort", Scalar::u16}, {"uint16", Scalar::u16},
        {"int", Scalar::i32},    {"int32", Scalar::i32},   {"uint", Scalar::u32},   {"uint32", Scalar::u32},
        {"float", Scalar::f32},  {"float32", Scalar::f32}, {"double", Scalar::f64}, {"float64", Scalar::f64},
    };
    for (const auto& n : names)
        if (n.name == name) return out = n.type, true;
    return false;
}

struct Property {
    std::string name;
    Scalar type = Scalar::f32;  // the item type for a list
    bool is_list = false;
    Scalar count_type = Scalar::u8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;

    const Property* find(std::string_view n) const {
        for (const Property& p : properties)
            if (p.name == n) return &p;
        return nullptr;
    }
};

enum class Format { ascii, binary_le, binary_be };

struct Header {
    Format format = Format::ascii;
    std::vector<Element> elements;
    size_t data_offset = 0;  // first byte after the end_header line
    size_t line_count = 0;   // header lines, so that ASCII data errors can name their line
};

std::string plural(uint64_t n, const std::string& name) {
    const std::string word = name == "vertex" ? "vertices" : (!name.empty() && name.back() == 's') ? name : name + "s";
    return std::to_string(n) + " " + word;
}

bool printable(char c) { return c >= 0x20 && c < 0x7f; }
// Names are repeated in messages, so they must not carry bytes that could break a message line.
bool printable(std::string_view text) { return std::all_of(text.begin(), text.end(), [](char c) { return printable(c); }); }

// File text quoted in a message: short, and with no byte that could break the one-line message.
std::string shown(std::string_view text) {
    std::string out = "'";
    for (char c : text.substr(0, 24)) out += printable(c) ? c : '?';
    return out + (text.size() > 24 ? "...'" : "'");
}

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

// The smallest number of bytes one element can occupy: what bounds the count a file can hold.
uint64_t min_element_bytes(const Element& e, Format format) {
    uint64_t bytes = 0;
    for (const Property& p : e.properties)
        bytes += format == Format::ascii ? 2 : scalar_size(p.is_list ? p.count_type : p.type);
    return bytes;
}

Header parse_header(const std::string& path, std::string_view file, const LoadOptions& options) {
    if (file.substr(0, 3) != "ply" || (file.size() > 3 && file[3] != '\n' && file[3] != '\r'))
        fail_file(path, "not a PLY file (it does not start with a 'ply' line)");
    Header h;
    bool have_format = false;
    size_t pos = 0;
    while (true) {
        if (pos >= file.size()) fail_file(path, "PLY header has no end_header line");
        size_t eol = file.find('\n', pos);
        if (eol == std::string_view::npos) eol = file.size();
        std::string_view line = file.substr(pos, eol - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = eol + 1;
        ++h.line_count;
        const auto where = "PLY header line " + std::to_string(h.line_count) + ": ";
        if (line.find('\0') != std::string_view::npos) fail_file(path, where + "contains binary bytes");
        const std::vector<std::string_view> w = split_words(line);
        if (h.line_count == 1 || w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "end_header") {
            if (w.size() != 1) fail_file(path, where + "unexpected text after end_header");
            break;
        }
        if (w[0] == "format") {
            if (w.size() != 3) fail_file(path, where + "expected 'format <type> <version>'");
            if (w[1] == "ascii") h.format = Format::ascii;
            else if (w[1] == "binary_little_endian") h.format = Format::binary_le;
            else if (w[1] == "binary_big_endian") h.format = Format::binary_be;
            else fail_file(path, where + "unsupported format " + shown(w[1]));
            have_format = true;
        } else if (w[0] == "element") {
            Element e;
            const char* end = w.size() == 3 ? w[2].data() + w[2].size() : nullptr;
            if (!end) fail_file(path, where + "expected 'element <name> <count>' with a count of 0 or more");
            const auto [ptr, ec] = std::from_chars(w[2].data(), end, e.count);
            if (ec == std::errc::result_out_of_range) fail_file(path, where + "element count " + shown(w[2]) + " is beyond any file");
            if (ec != std::errc() || ptr != end)
                fail_file(path, where + "expected 'element <name> <count>' with a count of 0 or more");
            e.name = std::string(w[1]);
            if (!printable(e.name)) fail_file(path, where + "bad element name " + shown(e.name));
            h.elements.push_back(std::move(e));
        } else if (w[0] == "property") {
            if (h.elements.empty()) fail_file(path, where + "property before any element");
            Property p;
            const bool list = w.size() == 5 && w[1] == "list";
            if (!(list || w.size() == 3) || !parse_scalar(w[list ? 3 : 1], p.type) ||
                (list && !parse_scalar(w[2], p.count_type)))
                fail_file(path, where + "expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
            if (list && !is_integer(p.count_type)) fail_file(path, where + "a list count must have an integer type");
            p.is_list = list;
            p.name = std::string(w.back());
            if (!printable(p.name)) fail_file(path, where + "bad property name " + shown(p.name));
            h.elements.back().properties.push_back(std::move(p));
        } else {
            fail_file(path, where + "unexpected " + shown(w[0]));
        }
    }
    if (!have_format) fail_file(path, "PLY header has no format line");
    h.data_offset = std::min(pos, file.size());

    // Counts are checked before anything is allocated: first against what the file could hold at
    // all (ASCII: the last value needs no separator), then against the configured limit. A file
    // that merely ends early is reported as truncated while reading, with the count it holds.
    const uint64_t data_bytes = file.size() - h.data_offset + (h.format == Format::ascii ? 1 : 0);
    for (const Element& e : h.elements) {
        const uint64_t each = min_element_bytes(e, h.format);
        if (each > 0 && e.count > data_bytes / each)
            fail_file(path, "header claims " + plural(e.count, e.name) + ", more than the file can hold");
        if (e.count > options.max_elements)
            fail_file(path, "header claims " + plural(e.count, e.name) + ", more than the limit of " +
                                std::to_string(options.max_elements) + " per element");
    }
    return h;
}

struct Truncated {};  // thrown by the readers when the data ends; the element loop names the count

template <class T>
T byte_swapped(T v) {
    if constexpr (sizeof(T) == 1) return v;
    else {
        using U = std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>;
        U u = std::bit_cast<U>(v);
        if constexpr (sizeof(T) == 2) u = __builtin_bswap16(u);
        else if constexpr (sizeof(T) == 4) u = __builtin_bswap32(u);
        else u = __builtin_bswap64(u);
        return std::bit_cast<T>(u);
    }
}

// Binary data; the byte order is a template parameter so that no value pays for a runtime check.
template <bool Swap>
class BinaryReader {
public:
    BinaryReader(const std::string& path, const char* begin, const char* end) : path_(path), p_(begin), end_(end) {}

    double real(Scalar t) {
        switch (t) {
            case Scalar::i8: return get<int8_t>();
            case Scalar::u8: return get<uint8_t>();
            case Scalar::i16: return get<int16_t>();
            case Scalar::u16: return get<uint16_t>();
            case Scalar::i32: return get<int32_t>();
            case Scalar::u32: return get<uint32_t>();
            case Scalar::f32: return get<float>();
            case Scalar::f64: return get<double>();
        }
        return 0.0;
    }
    int64_t integer_on_line(Scalar t) { return integer(t); }  // binary data has no lines
    int64_t integer(Scalar t) {  // only called with integer types (checked when the header is read)
        switch (t) {
            case Scalar::i8: return get<int8_t>();
            case Scalar::u8: return get<uint8_t>();
            case Scalar::i16: return get<int16_t>();
            case Scalar::u16: return get<uint16_t>();
            case Scalar::i32: return get<int32_t>();
            case Scalar::u32: return get<uint32_t>();
            default: return static_cast<int64_t>(real(t));
        }
    }
    size_t remaining() const { return static_cast<size_t>(end_ - p_); }
    void end_item() {}  // binary elements have no separator
    // What follows the last element (expect_end in read_body): padding (zeros, whitespace) only.
    void expect_end() {
        const bool padding = std::all_of(p_, end_, [](char c) { return c == '\0' || c == ' ' || c == '\n' || c == '\r' || c == '\t'; });
        if (!padding)
            fail_file(path_, std::to_string(end_ - p_) + " bytes of data after the last element the header declares "
                             "(its element counts are too small)");
    }
    // A list of n items must fit in what is left; checked before the items are read one by one.
    void expect_items(uint64_t n, Scalar t) {
        if (n > static_cast<uint64_t>(end_ - p_) / scalar_size(t)) throw Truncated{};
    }
    void skip(const Property& p) {
        uint64_t bytes = scalar_size(p.type);
        if (p.is_list) {
            const int64_t n = integer(p.count_type);
            if (n < 0) fail_file(path_, "a '" + p.name + "' list has a negative length");
            expect_items(static_cast<uint64_t>(n), p.type);
            bytes *= static_cast<uint64_t>(n);
        }
        advance(bytes);
    }
    // Skips a whole element of fixed size at once (no lists): unknown elements cost nothing.
    void skip_fixed(uint64_t count, uint64_t stride, uint64_t& done) {
        const uint64_t left = static_cast<uint64_t>(end_ - p_);
        if (count > left / stride) {
            done = left / stride;
            throw Truncated{};
        }
        p_ += count * stride;
        done = count;
    }

private:
    template <class T>
    T get() {
        if (static_cast<size_t>(end_ - p_) < sizeof(T)) throw Truncated{};
        T v;
        std::memcpy(&v, p_, sizeof(T));
        p_ += sizeof(T);
        if constexpr (Swap) v = byte_swapped(v);
        return v;
    }
    void advance(uint64_t bytes) {
        if (bytes > static_cast<uint64_t>(end_ - p_)) throw Truncated{};
        p_ += bytes;
    }

    const std::string& path_;
    const char* p_;
    const char* end_;
};

// ASCII data: whitespace-separated numbers; lines are counted only to name them in messages.
class AsciiReader {
public:
    AsciiReader(const std::string& path, const char* begin, const char* end, size_t line)
        : path_(path), p_(begin), end_(end), line_(line) {}

    double real(Scalar) {
        // A vertex's values are on its own line: one short of the header's count read the next line's first value in
        // its place, and the message named the next line ("is one value more").
        const std::string_view t = unsigned_plus(token(started_));
        started_ = true;
        double v = 0.0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (ec == std::errc::result_out_of_range) bad(t, "is out of range");
        if (ec != std::errc() || ptr != t.data() + t.size()) bad(t, "is not a number");
        return v;
    }
    // An integer of a face: on the face's line, as real() reads a vertex's values (a face one index short read the
    // next line's count as its last corner, and the message named the wrong line). Strips' lists, which may be
    // one long line or wrapped, are read with integer().
    int64_t integer_on_line(Scalar) {
        const bool same_line = started_;
        started_ = true;
        return parse_integer(unsigned_plus(token(same_line)));
    }
    int64_t integer(Scalar) { return parse_integer(unsigned_plus(token())); }
    int64_t parse_integer(std::string_view s) {
        int64_t v = 0;
        const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec == std::errc() && ptr == s.data() + s.size()) return v;
        // Some writers print integers as "3.000"; accept whole numbers, refuse anything else.
        double d = 0.0;
        const auto [dptr, dec] = std::from_chars(s.data(), s.data() + s.size(), d);
        if (dec != std::errc() || dptr != s.data() + s.size() || d != std::trunc(d) || std::fabs(d) > 9e15)
            bad(s, "is not an integer");
        return static_cast<int64_t>(d);
    }
    size_t remaining() const { return static_cast<size_t>(end_ - p_); }
    // Each element is one line: a value left before the line's end means the header and the data disagree
    // (read on, every later element would shift by it and load as other numbers).
    void end_item() {
        started_ = false;
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r')) ++p_;
        if (p_ == end_ || *p_ == '\n') return;
        const char* start = p_;
        while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
        bad({start, static_cast<size_t>(p_ - start)}, "is one value more than the header gives this element (one element a line)");
    }
    void expect_items(uint64_t, Scalar) {}  // items are read one by one; the data end bounds them
    // What follows the last element (expect_end in read_body): whitespace or padding only (zero bytes, a DOS
    // end-of-file mark, form feeds: files ending so loaded before the check).
    void expect_end() {
        const auto padding = [](char c) {
            return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == '\0' || c == '\x1a';
        };
        while (p_ < end_ && padding(*p_)) line_ += *p_++ == '\n';
        if (p_ == end_) return;
        bad(token(), "lies after the last element the header declares (its element counts are too small)");
    }
    void skip(const Property& p) {
        if (!p.is_list) {  // on the element's line, as real() reads
            token(started_);
            started_ = true;
            return;
        }
        const int64_t n = integer(p.count_type);
        if (n < 0) fail_file(path_, "line " + std::to_string(line_) + ": a '" + p.name + "' list has a negative length");
        for (int64_t i = 0; i < n; ++i) token();
    }

private:
    // from_chars refuses the leading '+' that printf("%+g") and some writers put.
    static std::string_view unsigned_plus(std::string_view t) {
        if (t.size() > 1 && t.front() == '+' && (std::isdigit(static_cast<unsigned char>(t[1])) || t[1] == '.'))
            t.remove_prefix(1);  // "+-5" stays refused
        return t;
    }
    // `same_line`: the element's values so far are on this line, and this one must be too.
    std::string_view token(bool same_line = false) {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) {
            if (*p_ == '\n' && same_line)
                fail_file(path_, "line " + std::to_string(line_) + ": holds fewer values than the header gives this element (one element a line)");
            line_ += *p_++ == '\n';
        }
        if (p_ == end_) throw Truncated{};
        const char* start = p_;
        while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
        return {start, static_cast<size_t>(p_ - start)};
    }
    [[noreturn]] void bad(std::string_view t, const char* what) {
        fail_file(path_, "line " + std::to_string(line_) + ": " + shown(t) + " " + what);
    }

    const std::string& path_;
    const char* p_;
    const char* end_;
    size_t line_;
    bool started_ = false;  // a value of the current element read (real(), skip() of a scalar, integer_on_line())
};

struct Target {
    const std::string& path;
    uint64_t vertex_count;  // from the header, so faces can be checked even before the vertices
    Mesh& mesh;
    // Faces of more than 3 corners: where their fans start in mesh.indices, and their corner counts. They are
    // cut properly once the vertices are read (a PLY may list its faces first): triangulate_polygons.
    std::vector<std::pair<size_t, uint32_t>> polygons = {};
    // Positions as the file gives them, where that is more than single precision holds (double or 32-bit
    // integer properties, text): recentre_far_model then keeps a model far from the file's origin in shape.
    std::vector<glm::dvec3> exact = {};
};

uint32_t checked_index(const Target& t, int64_t index, const char* what, uint64_t number) {
    if (index < 0 || static_cast<uint64_t>(index) >= t.vertex_count)
        fail_file(t.path, std::string(what) + " " + std::to_string(number) + " refers to vertex " +
                              std::to_string(index) + " but there are only " + std::to_string(t.vertex_count) +
                              " vertices");
    return static_cast<uint32_t>(index);
}

template <class Reader>
void read_vertices(Reader& r, const Element& e, Target& t, uint64_t& done) {
    static constexpr std::string_view slots[] = {"x", "y", "z", "nx", "ny", "nz"};
    std::vector<int> slot(e.properties.size(), -1);
    bool has_normals = true;
    for (int s = 0; s < 6; ++s) {
        const Property* p = e.find(slots[s]);
        if (p && p->is_list) fail_file(t.path, "vertex property '" + p->name + "' must not be a list");
        if (!p && s < 3) fail_file(t.path, "vertex element has no '" + std::string(slots[s]) + "' property");
        if (p) slot[p - e.properties.data()] = s;
        else has_normals = false;
    }
    if (!has_normals)
        for (int& s : slot) s = s >= 3 ? -1 : s;
    bool precise = std::is_same_v<Reader, AsciiReader>;
    for (const char* name : {"x", "y", "z"}) {
        const Scalar type = e.find(name)->type;
        precise = precise || type == Scalar::f64 || type == Scalar::i32 || type == Scalar::u32;
    }
    t.mesh.positions.resize(e.count);
    if (precise) t.exact.resize(e.count);
    if (has_normals) t.mesh.normals.resize(e.count);
    double v[6] = {};
    for (done = 0; done < e.count; ++done) {
        for (size_t k = 0; k < e.properties.size(); ++k) {
            if (slot[k] < 0) r.skip(e.properties[k]);
            else v[slot[k]] = r.real(e.properties[k].type);
        }
        r.end_item();
        t.mesh.positions[done] = glm::vec3(float(v[0]), float(v[1]), float(v[2]));
        if (precise) t.exact[done] = {v[0], v[1], v[2]};
        if (has_normals) t.mesh.normals[done] = glm::vec3(float(v[3]), float(v[4]), float(v[5]));
    }
}

// A model far from its file's origin, read in more than single precision, is stored about its own centre
// (Mesh::origin, as the OBJ reader does): a unit sphere 90,000 units out, from a double PLY, was rounded to
// 1/128 of a unit (its area 12.62 for 12.56, its shading in bands).
void recentre_far_model(Target& t) {
    if (t.exact.empty()) return;
    store_about_far_origin(t.mesh, t.exact);
    std::vector<glm::dvec3>().swap(t.exact);
}

// Faces: polygons are fan-triangulated around their first corner here, and the concave ones cut again by
// triangulate_polygons once every vertex is read.
template <class Reader>
void read_faces(Reader& r, const Element& e, const Property& list, Target& t, uint64_t& done) {
    std::vector<uint32_t> corners;
    // A triangle takes at least 4 bytes (a count and three indices), which bounds the reservation
    // by the data actually there, whatever the header claims.
    t.mesh.indices.reserve(t.mesh.indices.size() + 3 * std::min<uint64_t>(e.count, r.remaining() / 4));
    for (done = 0; done < e.count; ++done) {
        for (const Property& p : e.properties) {
            if (&p != &list) {
                r.skip(p);
                continue;
            }
            const int64_t n = r.integer_on_line(p.count_type);
            if (n < 3)
                fail_file(t.path, "face " + std::to_string(done) + " has " + std::to_string(n) +
                                      " vertices; a face needs at least 3");
            r.expect_items(static_cast<uint64_t>(n), p.type);
            corners.clear();
            for (int64_t i = 0; i < n; ++i) corners.push_back(checked_index(t, r.integer_on_line(p.type), "face", done));
            if (corners.size() > 3) t.polygons.emplace_back(t.mesh.indices.size(), uint32_t(corners.size()));
            for (size_t i = 1; i + 1 < corners.size(); ++i)
                t.mesh.indices.insert(t.mesh.indices.end(), {corners[0], corners[i], corners[i + 1]});
        }
        r.end_item();
    }
}

// Triangle strips, -1 between strips (all ones in unsigned lists: 0xFFFFFFFF, 0xFFFF, 0xFF, where
// they are not a vertex number). Odd triangles of a strip swap their first two corners so
// that all keep the strip's winding; triangles with a repeated corner only stitch strips
// together and are dropped.
template <class Reader>
void read_strips(Reader& r, const Element& e, const Property& list, Target& t, uint64_t& done) {
    for (done = 0; done < e.count; ++done) {
        for (const Property& p : e.properties) {
            if (&p != &list) {
                r.skip(p);
                continue;
            }
            const int64_t n = r.integer(p.count_type);
            if (n < 0) fail_file(t.path, "strip element " + std::to_string(done) + " has a negative length");
            r.expect_items(static_cast<uint64_t>(n), p.type);
            uint32_t a = 0, b = 0;
            uint64_t in_strip = 0;
            for (int64_t i = 0; i < n; ++i) {
                const int64_t value = r.integer(p.type);
                // The all-ones value of an unsigned list is -1 written unsigned: a restart wherever it cannot be
                // a vertex (a ushort list's 65535 for a model of 65536 vertices is one).
                const bool all_ones = (p.type == Scalar::u32 && value == 0xFFFFFFFF) ||
                                      (p.type == Scalar::u16 && value == 0xFFFF) || (p.type == Scalar::u8 && value == 0xFF);
                if (value == -1 || (all_ones && static_cast<uint64_t>(value) >= t.vertex_count)) {
                    in_strip = 0;
                    continue;
                }
                const uint32_t c = checked_index(t, value, "strip element", done);
                if (in_strip >= 2 && a != b && b != c && a != c) {
                    if (in_strip % 2 == 0) t.mesh.indices.insert(t.mesh.indices.end(), {a, b, c});
                    else t.mesh.indices.insert(t.mesh.indices.end(), {b, a, c});
                }
                a = b;
                b = c;
                ++in_strip;
            }
        }
        r.end_item();
    }
}

template <class Reader>
void skip_elements(Reader& r, const Element& e, Format format, uint64_t& done) {
    if (e.properties.empty()) return;  // occupies no bytes, however many the header claims
    if constexpr (!std::is_same_v<Reader, AsciiReader>) {
        bool fixed = true;
        for (const Property& p : e.properties) fixed = fixed && !p.is_list;
        if (fixed) return r.skip_fixed(e.count, min_element_bytes(e, format), done);
    }
    for (done = 0; done < e.count; ++done) {
        for (const Property& p : e.properties) r.skip(p);
        r.end_item();
    }
}

const Property* index_list(const Element& e) {
    const Property* p = e.find("vertex_indices");
    return p ? p : e.find("vertex_index");
}

template <class Reader>
void read_body(Reader& r, const Header& h, Target& t) {
    for (const Element& e : h.elements) {
        const Property* list = index_list(e);
        const bool faces = e.name == "face", strips = e.name == "tristrips";
        if ((faces || strips) && e.count > 0 && (!list || !list->is_list || !is_integer(list->type)))
            fail_file(t.path, "element '" + e.name + "' has no integer list property 'vertex_indices'");
        uint64_t done = 0;
        try {
            if (e.name == "vertex") read_vertices(r, e, t, done);
            else if (faces && e.count > 0) read_faces(r, e, *list, t, done);
            else if (strips && e.count > 0) read_strips(r, e, *list, t, done);
            else skip_elements(r, e, h.format, done);
        } catch (const Truncated&) {
            fail_file(t.path, "truncated: header promises " + plural(e.count, e.name) + " but the file ends after " +
                                  std::to_string(done));
        }
    }
    // Data beyond what the header declares was dropped without a word (a horse whose header said 1 face of its
    // 96,966 loaded as one triangle).
    r.expect_end();
}

// Each polygon's fan, read back into its corners (c0 c1 c2, c0 c2 c3, ...), triangulated in place.
void triangulate_polygons(Target& t) {
    std::vector<uint32_t> corners;
    for (const auto& [offset, count] : t.polygons) {
        uint32_t* fan = t.mesh.indices.data() + offset;
        corners.assign({fan[0], fan[1]});
        for (uint32_t i = 0; i + 2 < count; ++i) corners.push_back(fan[3 * i + 2]);
        if (triangulate_polygon(t.mesh.positions, corners, std::span<uint32_t>(fan, 3 * (size_t(count) - 2))) ==
            Triangulated::budget_spent)
            fail_file(t.path, "a face of " + std::to_string(count) +
                                  " corners is a concave polygon too large to cut into triangles here (split it into smaller faces)");
    }
}

}  // namespace

Mesh parse_ply(const std::string& path, std::string_view file, const LoadOptions& options) {
    const Header h = parse_header(path, file, options);
    uint64_t vertex_count = 0;
    int vertex_elements = 0;
    for (const Element& e : h.elements)
        if (e.name == "vertex") vertex_count = e.count, ++vertex_elements;
    if (vertex_elements != 1) fail_file(path, vertex_elements ? "PLY file has more than one vertex element" : "PLY file has no vertex element");
    if (vertex_count > std::numeric_limits<uint32_t>::max())
        fail_file(path, "header claims " + plural(vertex_count, "vertex") + ", more than 32-bit indices can address");

    Mesh mesh;
    mesh.source = path;
    Target target{path, vertex_count, mesh};
    const char* begin = file.data() + h.data_offset;
    const char* end = file.data() + file.size();
    constexpr bool little_host = std::endian::native == std::endian::little;
    if (h.format == Format::ascii) {
        AsciiReader r(path, begin, end, h.line_count + 1);
        read_body(r, h, target);
    } else if ((h.format == Format::binary_le) == little_host) {
        BinaryReader<false> r(path, begin, end);
        read_body(r, h, target);
    } else {
        BinaryReader<true> r(path, begin, end);
        read_body(r, h, target);
    }
    recentre_far_model(target);
    triangulate_polygons(target);
    return mesh;
}

}  // namespace stipple
