#include "io/png_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "core/error.hpp"
#include "io/output_file.hpp"

// Debian's libstb-dev is header-only for our purposes (there is a libstb.so, but the stb::stb
// target only adds the include folder), so the implementation lives here. The functions are made
// `static` so that they cannot interpose on, or be interposed by, the copy inside libstb.so that
// libtinygltf.so pulls in: each user keeps its own private copy.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBIW_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace stipple {
namespace {

size_t expected_bytes(const Image& image) {
    return static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
           static_cast<size_t>(image.channels);
}

// stb hands encoded chunks to this callback; we collect them so that the file itself is written
// with iostreams and a failure can name the real cause (errno) instead of stb's bare 0.
void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

std::string errno_text() { return errno != 0 ? std::strerror(errno) : "unknown I/O error"; }

}  // namespace

bool png_size_writable(int64_t width, int64_t height, int channels) {
    return width > 0 && height > 0 && (width * channels + 1) * height <= std::numeric_limits<int>::max();
}

namespace {

// The CRC-32 that PNG chunks carry (ISO 3309, as zlib's crc32).
uint32_t png_crc(const uint8_t* bytes, size_t size) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = 0; i < size; ++i) {
        crc ^= bytes[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

void put_big_endian(std::vector<uint8_t>& out, uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(value >> shift));
}

// stb_image_write writes no pHYs: one is put after IHDR (8 bytes of signature, then 25 of IHDR), where
// PNG wants it (before the image data).
void insert_resolution(std::vector<uint8_t>& png, double dpi) {
    const uint32_t per_metre = uint32_t(std::lround(dpi / 0.0254));
    std::vector<uint8_t> chunk;
    put_big_endian(chunk, 9);
    for (char c : {'p', 'H', 'Y', 's'}) chunk.push_back(uint8_t(c));
    put_big_endian(chunk, per_metre);
    put_big_endian(chunk, per_metre);
    chunk.push_back(1);  // unit: the metre
    put_big_endian(chunk, png_crc(chunk.data() + 4, chunk.size() - 4));
    png.insert(png.begin() + 33, chunk.begin(), chunk.end());
}

}  // namespace

void write_png(const std::string& path, const Image& image, double dpi) {
    if (image.width <= 0 || image.height <= 0 || image.channels < 1 || image.channels > 4)
        fail_file(path, "cannot write PNG: bad image size " + std::to_string(image.width) + "x" +
                            std::to_string(image.height) + "x" + std::to_string(image.channels));
    if (image.pixels.size() != expected_bytes(image))
        fail_file(path, "cannot write PNG: pixel buffer holds " + std::to_string(image.pixels.size()) +
                            " bytes, expected " + std::to_string(expected_bytes(image)));
    if (static_cast<int64_t>(image.width) * image.channels > std::numeric_limits<int>::max())
        fail_file(path, "cannot write PNG: row too wide");
    if (!png_size_writable(image.width, image.height, image.channels))
        fail_file(path, "cannot write PNG: " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                            " is more than a PNG of 2 GiB of pixels; lower --dpi or the page size, or write SVG or PDF");

    std::vector<uint8_t> encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, image.channels,
                                image.pixels.data(), image.width * image.channels))
        fail_file(path, "cannot write PNG: encoding failed");
    if (dpi > 0.0 && encoded.size() > 33) insert_resolution(encoded, dpi);

    write_output(path, "cannot write PNG",
                 std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

Image read_png(const std::string& path) {
    // Read the bytes ourselves: stbi_load's failure reasons do not tell "missing" from "corrupt".
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail_file(path, "cannot read PNG: no such file");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_file(path, "cannot read PNG: " + errno_text());
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) fail_file(path, "cannot read PNG: " + errno_text());
    if (bytes.empty()) fail_file(path, "cannot read PNG: file is empty");
    if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        fail_file(path, "cannot read PNG: file too large");

    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                                          &channels, 0);
    if (data == nullptr) {
        const char* reason = stbi_failure_reason();
        fail_file(path, std::string("cannot read PNG: ") + (reason ? reason : "not a readable image"));
    }
    Image image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    image.pixels.assign(data, data + expected_bytes(image));
    stbi_image_free(data);
    return image;
}

double fraction_differing(const Image& a, const Image& b, int tolerance) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        fail("fraction_differing: image sizes differ (" + std::to_string(a.width) + "x" +
             std::to_string(a.height) + "x" + std::to_string(a.channels) + " vs " + std::to_string(b.width) +
             "x" + std::to_string(b.height) + "x" + std::to_string(b.channels) + ")");
    if (a.pixels.size() != expected_bytes(a) || b.pixels.size() != expected_bytes(b))
        fail("fraction_differing: pixel buffer does not match the image size");
    const size_t pixel_count = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
    if (pixel_count == 0) return 0.0;

    const size_t channels = static_cast<size_t>(a.channels);
    size_t differing = 0;
    for (size_t p = 0; p < pixel_count; ++p) {
        for (size_t c = 0; c < channels; ++c) {
            const int d = std::abs(int(a.pixels[p * channels + c]) - int(b.pixels[p * channels + c]));
            if (d > tolerance) {
                ++differing;
                break;
            }
        }
    }
    return static_cast<double>(differing) / static_cast<double>(pixel_count);
}

uint8_t luminance(const Image& image, int x, int y) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height)
        fail("luminance: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside " +
             std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
    if (image.channels < 1 || image.pixels.size() != expected_bytes(image))
        fail("luminance: pixel buffer does not match the image size");
    const size_t at = (static_cast<size_t>(y) * image.width + x) * image.channels;
    if (image.channels < 3) return image.pixels[at];  // grey or grey+alpha
    const double luma =
        0.299 * image.pixels[at] + 0.587 * image.pixels[at + 1] + 0.114 * image.pixels[at + 2];
    return static_cast<uint8_t>(std::min(255.0, luma + 0.5));
}

}  // namespace stipple
