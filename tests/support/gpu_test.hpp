#pragma once
// A Vulkan context per test with the validation layer on; a validation message fails the test.
// Header-only so that CPU-only tests do not link Vulkan.
#include <memory>

#include <gtest/gtest.h>

#include "gpu/context.hpp"
#include "render/offscreen.hpp"

namespace stipple::test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override {
        gpu::ContextOptions options;
        options.validation = true;
        context = std::make_unique<gpu::Context>(options);
    }
    void TearDown() override {
        uint32_t messages = context->validation_message_count();
        context.reset();  // destruction can report leaks too; those land on stderr
        EXPECT_EQ(messages, 0u) << "Vulkan validation messages (printed above)";
    }
    std::unique_ptr<gpu::Context> context;
};

// Share of covered pixels that carry ink (red channel below 128), and ink outside the coverage.
struct InkFigures {
    size_t covered = 0;
    size_t inked_inside = 0;
    size_t inked_outside = 0;
    size_t non_white_outside = 0;
    double ink_fraction() const { return covered ? double(inked_inside) / double(covered) : 0.0; }
};

inline InkFigures measure_ink(const RenderedFrame& frame) {
    InkFigures f;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        const uint8_t* p = &frame.color.pixels[4 * i];
        bool inside = frame.depth[i] < 1.0f;
        bool inked = p[0] < 128;
        if (inside) {
            ++f.covered;
            f.inked_inside += inked;
        } else {
            f.inked_outside += inked;
            f.non_white_outside += (p[0] != 255 || p[1] != 255 || p[2] != 255);
        }
    }
    return f;
}

}  // namespace stipple::test
