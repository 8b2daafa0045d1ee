#pragma once
// Images larger than one render target (prints: an A3 page at 600 dpi is ~7000 x 9900 pixels), drawn in
// tiles. Each tile is a render target showing its rectangle of the full view's frustum; a tile's
// projection keeps the full view's pixels per unit, so every density (§2.1-2.3), every selected polygon
// and every stipple is the same as in one big image, and the tiles join without seams.
#include <optional>

#include "io/png_io.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

// The projection showing the pixel rectangle [x0, x0 + w) x [y0, y0 + h) of a full_w x full_h view
// (rows from the top, as the renderer's negative-height viewport puts them).
glm::mat4 tile_projection(const glm::mat4& proj, VkExtent2D full, VkOffset2D origin, VkExtent2D tile);

// The largest image one render target can draw on this device: the compute splat (and the object-space
// lines) read the frame as a storage buffer of one 32-bit word a pixel, which must fit the device's largest
// storage buffer (lavapipe: 128 MiB, 33.5 million pixels).
bool fits_one_target(const gpu::Context& context, VkExtent2D extent);
// The side of the largest square tile that fits one target.
uint32_t largest_tile_side(const gpu::Context& context);

// Draws `view` (its extent the whole image) in tiles of at most `max_tile` pixels a side (and no larger
// than one target holds: largest_tile_side) and returns the
// opaque colour image. `renderer` holds the objects; the splat paths need targets that allow it (ours do).
// Tiles overlap by the reach of the largest dot and keep only their own pixels, so they join without seams.
// `region`, when given, is the part of the image drawn and returned (a print fitted to its drawing: the
// drawing's box of a larger image); its tiles reach past it by the same overlap.
Image render_tiled(const gpu::Context& context, StippleRenderer& renderer, const FrameView& view, uint32_t max_tile,
                   const std::optional<VkRect2D>& region = std::nullopt);

}  // namespace stipple
