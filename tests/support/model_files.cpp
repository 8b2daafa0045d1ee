#include "support/model_files.hpp"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace stipple::test {

std::string write_file(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write test file " + path.string());
    return path.string();
}

std::string base64(std::string_view bytes) {
    static constexpr char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

std::string make_glb(const std::string& json, const std::string& bin) {
    std::string json_chunk = json, bin_chunk = bin;
    while (json_chunk.size() % 4) json_chunk += ' ';
    while (bin_chunk.size() % 4) bin_chunk += '\0';
    const uint32_t total = 12 + 8 + static_cast<uint32_t>(json_chunk.size()) +
                           (bin_chunk.empty() ? 0 : 8 + static_cast<uint32_t>(bin_chunk.size()));
    ByteWriter w;
    w.put<uint32_t>(0x46546C67).put<uint32_t>(2).put<uint32_t>(total);  // "glTF", version 2
    w.put<uint32_t>(static_cast<uint32_t>(json_chunk.size())).put<uint32_t>(0x4E4F534A);  // "JSON"
    std::string out = w.bytes() + json_chunk;
    if (!bin_chunk.empty()) {
        ByteWriter c;
        c.put<uint32_t>(static_cast<uint32_t>(bin_chunk.size())).put<uint32_t>(0x004E4942);  // "BIN\0"
        out += c.bytes() + bin_chunk;
    }
    return out;
}

}  // namespace stipple::test
