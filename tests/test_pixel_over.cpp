// The viewer's panel laid over a frame on the host (app/pixel_over.hpp): every premultiplied layer
// pixel over every frame channel gives what blending the panel's triangles over the frame gives,
// c_layer + c_frame * (255 - a) / 255, rounded to the nearest unit, for each channel whatever its order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "app/pixel_over.hpp"

namespace {

using stipple::app::pixel_over;
using stipple::app::pixels_over;

uint32_t word(uint32_t c0, uint32_t c1, uint32_t c2, uint32_t a) { return c0 | c1 << 8 | c2 << 16 | a << 24; }

TEST(PixelOver, EveryAlphaChannelAndFrameValueRoundsToTheNearestUnit) {
    size_t checked = 0;
    for (uint32_t a = 0; a < 256; ++a)
        for (uint32_t c = 0; c <= a; c += 1 + (a > 64) * 3)  // premultiplied: a channel never exceeds alpha
            for (uint32_t d = 0; d < 256; ++d) {
                const uint32_t frame = word(d, 255 - d, d / 2, 255);
                const uint32_t layer = word(c, a - c, c / 3, a);
                const uint32_t out = pixel_over(layer, frame);
                const auto expect = [&](uint32_t layer_c, uint32_t frame_c) {
                    return layer_c + uint32_t(std::lround(double(frame_c) * (255 - a) / 255.0));
                };
                ASSERT_EQ(out & 0xFF, expect(c, d)) << "a " << a << " c " << c << " d " << d;
                ASSERT_EQ(out >> 8 & 0xFF, expect(a - c, 255 - d));
                ASSERT_EQ(out >> 16 & 0xFF, expect(c / 3, d / 2));
                ASSERT_EQ(out >> 24, expect(a, 255)) << "alpha: the layer's over an opaque frame";
                ++checked;
            }
    EXPECT_GT(checked, 1'000'000u);
}

TEST(PixelOver, TransparentLeavesTheFrameAndOpaqueReplacesIt) {
    for (uint32_t frame : {0u, 0xFFFFFFFFu, 0x80402010u, 0xFF99D9FFu}) {
        EXPECT_EQ(pixel_over(0u, frame), frame);
        EXPECT_EQ(pixel_over(0xFF123456u, frame), 0xFF123456u);
    }
}

TEST(PixelOver, ARowInPlace) {
    std::vector<uint32_t> frame(37), layer(37);
    for (uint32_t i = 0; i < 37; ++i) {
        frame[i] = word(i * 7 % 256, i * 13 % 256, i * 29 % 256, 255);
        const uint32_t a = i * 41 % 256;
        layer[i] = word(a / 2, a / 3, a, a);
    }
    std::vector<uint32_t> out = frame, portable = frame;
    pixels_over(out.data(), layer.data(), out.size());  // AVX2 where the processor has it
    stipple::app::pixels_over_portable(portable.data(), layer.data(), portable.size());
    for (size_t i = 0; i < out.size(); ++i) {
        EXPECT_EQ(out[i], pixel_over(layer[i], frame[i])) << i;
        EXPECT_EQ(portable[i], out[i]) << i;
    }
}

}  // namespace
