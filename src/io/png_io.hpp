#pragma once
// 8-bit PNG reading and writing, plus the few image comparisons that tests across the project
// share (golden-image checks, "is anything drawn here" checks).
#include <cstdint>
#include <string>
#include <vector>

namespace stipple {

// Plain 8-bit image: row-major, top row first, `channels` interleaved bytes per pixel (1..4).
struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<uint8_t> pixels;  // width * height * channels bytes
};

// Writes `image` as PNG, creating missing parent folders. `dpi` > 0 records the resolution (a pHYs
// chunk), so that a print image prints at its page size rather than at a viewer's guess of 72 or 96 dpi.
// Throws stipple::Error("<path>: cannot write PNG ...") on a malformed image or an I/O failure.
void write_png(const std::string& path, const Image& image, double dpi = 0.0);

// Whether write_png can encode an image of this size (stb_image_write sizes its filtered copy,
// (width * channels + 1) * height bytes, in an int): callers that draw large images ask first.
bool png_size_writable(int64_t width, int64_t height, int channels);

// Reads a PNG (or any format stb_image knows) keeping its own channel count.
// Throws stipple::Error("<path>: ...") with one line when the file is missing or not an image.
Image read_png(const std::string& path);

// Share (0..1) of pixels where any channel differs by more than `tolerance`.
// Throws stipple::Error when the sizes or channel counts differ. Two empty images give 0.
double fraction_differing(const Image& a, const Image& b, int tolerance);

// Rec. 601 luma of pixel (x, y), 0..255; for 1-2 channels the first channel (grey) itself.
// Alpha is ignored. Throws stipple::Error when (x, y) is outside the image.
uint8_t luminance(const Image& image, int x, int y);

}  // namespace stipple
