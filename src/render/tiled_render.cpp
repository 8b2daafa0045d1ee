#include "render/tiled_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "core/error.hpp"
#include "gpu/context.hpp"
#include "render/density_formulas.hpp"
#include "render/object_gpu.hpp"
#include "render/offscreen.hpp"
#include "render/stipple_renderer.hpp"

namespace stipple {

glm::mat4 tile_projection(const glm::mat4& proj, VkExtent2D full, VkOffset2D origin, VkExtent2D tile) {
    // NDC x runs left to right over the full width; NDC y runs bottom to top while rows run top down.
    const float sx = float(full.width) / float(tile.width), sy = float(full.height) / float(tile.height);
    const float cx = (2.0f * float(origin.x) + float(tile.width)) / float(full.width) - 1.0f;
    const float cy = 1.0f - (2.0f * float(origin.y) + float(tile.height)) / float(full.height);
    glm::mat4 to_tile(1.0f);  // ndc' = s * (ndc - c), as a clip-space transform (it keeps w)
    to_tile[0][0] = sx;
    to_tile[1][1] = sy;
    to_tile[3][0] = -sx * cx;
    to_tile[3][1] = -sy * cy;
    return to_tile * proj;
}

bool fits_one_target(const gpu::Context& context, VkExtent2D extent) {
    return uint64_t(extent.width) * extent.height <= context.max_pixel_words() &&
           extent.width <= context.properties.limits.maxImageDimension2D &&
           extent.height <= context.properties.limits.maxImageDimension2D;
}

uint32_t largest_tile_side(const gpu::Context& context) {
    uint32_t side = uint32_t(std::sqrt(double(context.max_pixel_words())));
    while (side > 16 && !fits_one_target(context, {side, side})) --side;
    return std::min(side, context.properties.limits.maxImageDimension2D);
}

// How far beyond a tile its dots reach: at print detail a dot is hidden or kept as a whole by the depth at
// its centre (splat.comp, kWholeDot), which must lie in the target that draws it. A dot astride a tile's
// edge with its centre in the next tile read the depth at this tile's edge instead: on a sloped surface
// its part in this tile was dropped (0.34% of the ink of a 105 x 148 mm print at 200 dpi lay in such seams).
uint32_t dot_reach(StippleRenderer& renderer, const FrameView& view) {
    float side = 0.0f;
    for (size_t i = 0; i < renderer.object_count(); ++i)
        side = std::max(side, 2.0f * stipple_ink_radius(renderer.params(i).point_size) * view.detail_scale *
                                  formulas::kMaxStippleScale);  // enlarged where the candidates cannot carry the density
    // Raskar-Cohen lines: their round caps are points, dropped where their centre lies beyond the target (a 48-px
    // outline of the default scene lost 42 pixels along a seam), and a segment wholly beyond it is clipped before it
    // is widened; their width bounds the thinned one.
    for (size_t i = 0; i < renderer.object_count(); ++i) {
        const ObjectParams& params = renderer.params(i);
        if (params.silhouette_lines) side = std::max(side, params.silhouette_width * std::max(1.0f, view.detail_scale));
    }
    return uint32_t(std::ceil(0.5f * side)) + 2;
}

Image render_tiled(const gpu::Context& context, StippleRenderer& renderer, const FrameView& view, uint32_t max_tile,
                   const std::optional<VkRect2D>& region) {
    const VkExtent2D full = view.extent;
    const VkRect2D part_drawn = region.value_or(VkRect2D{{0, 0}, full});
    const uint32_t rx0 = uint32_t(part_drawn.offset.x), ry0 = uint32_t(part_drawn.offset.y);
    const uint32_t rx1 = rx0 + part_drawn.extent.width, ry1 = ry0 + part_drawn.extent.height;
    STIPPLE_CHECK(part_drawn.offset.x >= 0 && part_drawn.offset.y >= 0 && rx1 <= full.width && ry1 <= full.height &&
                      rx1 > rx0 && ry1 > ry0,
                  "render_tiled: the region lies inside the image");
    const uint32_t largest = largest_tile_side(context);
    uint32_t limit = std::min<uint32_t>(max_tile, largest);
    STIPPLE_CHECK(limit >= 16, "render_tiled: tiles of at least 16 pixels");
    Image image;
    image.width = int(rx1 - rx0);
    image.height = int(ry1 - ry0);
    image.channels = 4;
    image.pixels.resize(size_t(image.width) * image.height * 4);
    // Each tile is drawn with a guard band of `margin` pixels of its neighbours around it (where the image
    // has them) and only its own pixels kept. One tile when the whole image fits; a part of the image has
    // the band too (dots centred beyond its edges reach into it).
    const bool whole = rx0 == 0 && ry0 == 0 && rx1 == full.width && ry1 == full.height;
    const bool one = whole && full.width <= limit && full.height <= limit;
    const uint32_t reach = one ? 0u : dot_reach(renderer, view);
    // A tile holds its guard band and some pixels of its own: where the dots reach farther than a small tile allows
    // (a print fitted to its drawing enlarges them up to 4 times), the tiles grow, as far as one target holds.
    if (!one) limit = std::max(limit, std::min(largest, 2 * reach + 64));
    const uint32_t margin = std::min(reach, (limit - 16) / 2);
    const uint32_t step = one ? std::max(full.width, full.height) : limit - 2 * margin;
    // One target at a time, made again where the tile's size changes (the first and last of a row or column
    // are cut short): one kept per size held up to nine to the end, 5.9 GB for a 16384-px image where one
    // tile and the image take 2.4.
    std::unique_ptr<OffscreenTarget> target;
    VkExtent2D target_extent{};
    for (uint32_t y0 = ry0; y0 < ry1; y0 += step)
        for (uint32_t x0 = rx0; x0 < rx1; x0 += step) {
            const uint32_t x1 = std::min(rx1, x0 + step), y1 = std::min(ry1, y0 + step);
            const uint32_t gx0 = x0 - std::min(x0, margin), gy0 = y0 - std::min(y0, margin);
            const uint32_t gx1 = std::min(full.width, x1 + margin), gy1 = std::min(full.height, y1 + margin);
            const VkExtent2D tile{gx1 - gx0, gy1 - gy0};
            if (!target || target_extent.width != tile.width || target_extent.height != tile.height) {
                target.reset();  // freed before the next is made
                target = std::make_unique<OffscreenTarget>(context, tile);
                target_extent = tile;
            }
            FrameView part = view;
            part.extent = tile;
            part.camera.proj = tile_projection(view.camera.proj, full, VkOffset2D{int32_t(gx0), int32_t(gy0)}, tile);
            // The densities are the full image's: the tile's projection scales pixels per unit back up to them.
            part.detail_scale = view.detail_scale;
            // Counted (--stats), each tile draws the whole drawing's stipples, so that the last tile's counts are
            // the image's: culled to its own viewport it counted only its own.
            if (renderer.counts_drawn() && !one) part.cull_outside_view = false;
            const RenderedFrame frame = target->render(renderer, part);
            for (uint32_t y = y0; y < y1; ++y)
                std::memcpy(&image.pixels[(size_t(y - ry0) * image.width + (x0 - rx0)) * 4],
                            &frame.color.pixels[(size_t(y - gy0) * tile.width + (x0 - gx0)) * 4], size_t(x1 - x0) * 4);
        }
    return image;
}

}  // namespace stipple
