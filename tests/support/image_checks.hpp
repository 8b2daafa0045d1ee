#pragma once
// Figures read from the images the command line writes (PNG screenshots, frames).
#include <cstddef>

#include "io/png_io.hpp"

namespace stipple::test {

// Pixels darker than mid-grey: the ink of a stipple drawing on white paper.
inline size_t ink_pixels(const Image& image) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += luminance(image, x, y) < 128;
    return n;
}

}  // namespace stipple::test
