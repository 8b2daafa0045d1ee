#pragma once
// Figures read from the images the command line writes (PNG screenshots, frames).
#include <cstddef>

#include <glm/glm.hpp>

#include "io/png_io.hpp"

namespace stipple::test {

// Pixels darker than mid-grey: the ink of a stipple drawing on white paper.
inline size_t ink_pixels(const Image& image) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += luminance(image, x, y) < 128;
    return n;
}

// The mean ink (1 - luminance, 0..1) of `image` where `mask` is white: what `stipple tone` prints per cell.
inline double mean_ink_inside(const Image& image, const Image& mask) {
    double ink = 0.0;
    size_t covered = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (luminance(mask, x, y) > 127) ink += 1.0 - luminance(image, x, y) / 255.0, ++covered;
    return covered ? ink / double(covered) : 0.0;
}

// Whether `colour` lies on the way from `paper` to `ink` (paper + a (ink - paper) for some a), within `tolerance`
// a channel: what any amount of one ink over the paper leaves, a fractional dot's or overlapping dots' alike.
// `a` is read from the channel where the ink is farthest from the paper.
inline bool on_the_way(glm::vec3 colour, glm::vec3 paper, glm::vec3 ink, float tolerance = 3.0f / 255.0f) {
    int channel = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(ink[k] - paper[k]) > std::abs(ink[channel] - paper[channel])) channel = k;
    const float a = (colour[channel] - paper[channel]) / (ink[channel] - paper[channel]);
    return glm::all(glm::lessThan(glm::abs(colour - (paper + a * (ink - paper))), glm::vec3(tolerance)));
}

}  // namespace stipple::test
