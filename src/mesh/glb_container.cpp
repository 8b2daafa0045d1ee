#include "mesh/glb_container.hpp"

#include <cstdint>

#include "core/error.hpp"

namespace stipple {

namespace {

uint32_t little_endian_u32(std::string_view bytes, size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
}

}  // namespace

GlbChunks split_glb(const std::string& name, std::string_view bytes) {
    if (bytes.substr(0, 4) != "glTF") fail_file(name, "not a binary glTF file (it does not start with 'glTF')");
    if (bytes.size() < 12)
        fail_file(name, "GLB header: the file ends after " + std::to_string(bytes.size()) + " bytes, within its 12-byte header");
    const uint32_t version = little_endian_u32(bytes, 4), length = little_endian_u32(bytes, 8);
    if (version == 1) fail_file(name, "glTF 1.0 is not supported (convert to glTF 2.0)");
    if (version != 2) fail_file(name, "GLB header: version " + std::to_string(version) + " is not supported (only 2)");
    if (length > bytes.size())
        fail_file(name, "GLB header: length " + std::to_string(length) + " is more than the file's " + std::to_string(bytes.size()) + " bytes");
    if (length < 20) fail_file(name, "GLB: the file ends before its JSON chunk");
    const uint32_t json_length = little_endian_u32(bytes, 12);
    if (little_endian_u32(bytes, 16) != 0x4E4F534A) fail_file(name, "GLB: the first chunk is not JSON");
    if (json_length == 0 || json_length > length - 20)
        fail_file(name, "GLB: the JSON chunk's length " + std::to_string(json_length) + " does not fit in the file");
    GlbChunks chunks;
    chunks.json = bytes.substr(20, json_length);
    const size_t bin_at = 20 + size_t{json_length};
    if (bin_at + 8 <= length && little_endian_u32(bytes, bin_at + 4) == 0x004E4942) {
        const uint32_t bin_length = little_endian_u32(bytes, bin_at);
        if (bin_length > length - bin_at - 8)
            fail_file(name, "GLB: the BIN chunk's length " + std::to_string(bin_length) + " reaches past the end of the file");
        chunks.has_bin = true;
        chunks.bin = bytes.substr(bin_at + 8, bin_length);
    }
    return chunks;
}

std::string join_glb(std::string_view json, std::string_view bin) {
    auto put_u32 = [](std::string& out, uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
    };
    const size_t json_padded = (json.size() + 3) / 4 * 4, bin_padded = (bin.size() + 3) / 4 * 4;
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out, static_cast<uint32_t>(12 + 8 + json_padded + (bin.empty() ? 0 : 8 + bin_padded)));
    put_u32(out, static_cast<uint32_t>(json_padded));
    put_u32(out, 0x4E4F534A);  // JSON
    out += json;
    out.append(json_padded - json.size(), ' ');
    if (!bin.empty()) {
        put_u32(out, static_cast<uint32_t>(bin_padded));
        put_u32(out, 0x004E4942);  // BIN
        out += bin;
        out.append(bin_padded - bin.size(), '\0');
    }
    return out;
}

}  // namespace stipple
