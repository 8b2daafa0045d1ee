#pragma once
// Small model files written by tests: raw bytes, binary PLY bodies in either byte order, base64
// for embedded glTF buffers and the GLB container.
#include <bit>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

namespace stipple::test {

// Writes `bytes` to `path` (binary, replacing it) and returns the path as a string.
std::string write_file(const std::filesystem::path& path, std::string_view bytes);

// Appends binary values in the chosen byte order (PLY bodies, glTF buffers).
class ByteWriter {
public:
    explicit ByteWriter(bool big_endian = false) : big_endian_(big_endian) {}

    template <class T>
    ByteWriter& put(T value) {
        char raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        const bool swap = big_endian_ != (std::endian::native == std::endian::big);
        for (size_t i = 0; i < sizeof(T); ++i) bytes_ += raw[swap ? sizeof(T) - 1 - i : i];
        return *this;
    }
    const std::string& bytes() const { return bytes_; }

private:
    bool big_endian_;
    std::string bytes_;
};

std::string base64(std::string_view bytes);

// A .glb container around a JSON document and an optional binary chunk (both padded as required).
std::string make_glb(const std::string& json, const std::string& bin);

}  // namespace stipple::test
