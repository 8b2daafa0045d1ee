// The depth pass's result as words (set 1, kBindingSceneDepthTexels; X8_D24 or float bits, one a pixel,
// row-major from the top row), for the passes that test stipples against it themselves: the compute splat
// and the points' outline shift (stipple.vert). Compared as the rasteriser's LESS_OR_EQUAL test sees them.
#ifndef SCENE_DEPTH_H
#define SCENE_DEPTH_H

// The depth pass's format: 24-bit unorm (X8_D24 words) or 32-bit float (the words are float bits).
layout(constant_id = kSpecDepthUnorm24) const bool kDepthUnorm24 = true;
// As texels: a software GPU gathers them, where it loads a storage buffer lane by lane.
layout(set = 1, binding = kBindingSceneDepthTexels) uniform usamplerBuffer scene_depth_texels;

uint scene_depth_at(uint at) { return texelFetch(scene_depth_texels, int(at)).x; }

// Whether a stipple at window depth z is hidden at a pixel whose depth-pass word is given, or no
// surface covers the pixel; compared as the rasteriser's LESS_OR_EQUAL test sees it (quantised).
bool hidden_or_uncovered(float z, uint word) {
    if (kDepthUnorm24) {
        uint surface = word & 0xFFFFFFu;
        return surface == 0xFFFFFFu || uint(z * 16777215.0 + 0.5) > surface;
    }
    float surface = uintBitsToFloat(word);
    return surface >= 1.0 || z > surface;
}

// Whether no surface covers the pixel (beyond the object's outline).
bool uncovered(uint word) {
    if (kDepthUnorm24) return (word & 0xFFFFFFu) == 0xFFFFFFu;
    return uintBitsToFloat(word) >= 1.0;
}

#endif
