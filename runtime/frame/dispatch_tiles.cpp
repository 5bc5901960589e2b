#include "frame/dispatch_tiles.h"

#include <algorithm>
#include <cmath>

namespace fg {

namespace {

// Pixels from the fovea's centre that the shader's float arithmetic may put on the other side of a
// boundary.
constexpr double kMarginPixels = 1.0;

struct Grid {
    std::uint32_t width, height;   // cells of the region's grid
    std::uint32_t scale;           // pixels per cell along each axis
    bool even_only;                // a cell stands for its even pixel alone (the periphery)
};

Grid region_grid(std::uint32_t width, std::uint32_t height, TileRegion region) {
    if (region == TileRegion::Fovea || region == TileRegion::Whole) return {width, height, 1, false};
    return {(width + 1) / 2, (height + 1) / 2, 2, region == TileRegion::Periphery};
}

}  // namespace

const char* tile_region_name(TileRegion region) {
    switch (region) {
        case TileRegion::Fovea: return "fovea";
        case TileRegion::FoveaLevel1: return "fovea_L1";
        case TileRegion::Periphery: return "periphery";
        case TileRegion::Fill: return "fill";
        case TileRegion::Whole: return "whole";
    }
    return "?";
}

std::array<std::uint32_t, 3> tile_dispatch_groups(std::size_t tiles) {
    if (tiles <= kTileRow) return {static_cast<std::uint32_t>(tiles), 1, 1};
    return {kTileRow, static_cast<std::uint32_t>((tiles + kTileRow - 1) / kTileRow), 1};
}

std::uint32_t dispatch_tile_capacity(std::uint32_t width, std::uint32_t height, TileRegion region) {
    Grid g = region_grid(width, height, region);
    auto groups = tile_dispatch_groups(std::size_t((g.width + 7) / 8) * ((g.height + 7) / 8));
    return groups[0] * groups[1];
}

std::vector<std::uint32_t> list_dispatch_tiles(const GpuFrame& frame, int view, TileRegion region, OutsideLens outside) {
    const std::uint32_t width = frame.eye_size.x, height = frame.eye_size.y;
    const GpuView& v = frame.views[view];
    // fg_fovea_centre and fg_periphery in common.glsl, in pixels.
    const double cx = (v.lens_radii.x > 0.0f ? v.lens_centre.x : 0.5) * width;
    const double cy = (v.lens_radii.x > 0.0f ? v.lens_centre.y : 0.5) * height;
    const double half = 0.5 * height;
    const double blend_start = frame.fovea_radius * half;                                      // fg_periphery > 0 beyond
    const double periphery = (frame.fovea_radius + std::max(frame.fovea_blend, 1e-6f)) * half;  // fg_periphery >= 1 beyond
    const Grid g = region_grid(width, height, region);
    // The lens ellipse in pixels (fg_outside_lens). A coarse cell tests its block's centre against
    // radii grown by the block: a tile's pixels grown by a cell and the margin hold every point the
    // shader may find inside.
    const bool lens = outside == OutsideLens::Left && v.lens_radii.x > 0.0f;
    const double lens_rx = v.lens_radii.x * width, lens_ry = v.lens_radii.y * height;
    const double lens_grow = g.scale + kMarginPixels;
    std::vector<std::uint32_t> tiles;
    for (std::uint32_t ty = 0; ty * 8 < g.height; ++ty)
        for (std::uint32_t tx = 0; tx * 8 < g.width; ++tx) {
            // The centres of the tile's pixels (of its even pixels for the periphery) span a box.
            auto span = [&](std::uint32_t t, std::uint32_t cells, std::uint32_t pixels) {
                std::uint32_t first = t * 8, last = std::min(first + 8, cells) - 1;
                double lo = first * g.scale + 0.5, hi = last * g.scale + 0.5;
                if (!g.even_only) hi = std::min<double>((last + 1) * g.scale, pixels) - 0.5;
                return std::pair{lo, hi};
            };
            auto [x0, x1] = span(tx, g.width, width);
            auto [y0, y1] = span(ty, g.height, height);
            const double nearest = std::hypot(std::clamp(cx, x0, x1) - cx, std::clamp(cy, y0, y1) - cy);
            const double farthest = std::hypot(std::max(cx - x0, x1 - cx), std::max(cy - y0, y1 - cy));
            if (lens) {
                auto reach = [&](double lo, double hi, double centre, double radius) {
                    return (std::clamp(centre, lo - lens_grow, hi + lens_grow) - centre) / radius;
                };
                const double qx = reach(x0, x1, cx, lens_rx), qy = reach(y0, y1, cy, lens_ry);
                if (qx * qx + qy * qy > 1.0) continue;
            }
            bool takes = false;
            switch (region) {
                case TileRegion::Fovea:
                case TileRegion::FoveaLevel1: takes = nearest < periphery + kMarginPixels; break;
                case TileRegion::Periphery: takes = farthest >= periphery - kMarginPixels; break;
                case TileRegion::Fill: takes = farthest > blend_start - kMarginPixels; break;
                case TileRegion::Whole: takes = true; break;
            }
            if (takes) tiles.push_back(tx | ty << 16);
        }
    auto groups = tile_dispatch_groups(tiles.size());
    tiles.resize(std::size_t(groups[0]) * groups[1], kNoTile);
    return tiles;
}

std::size_t SampledTiles::count() const { return static_cast<std::size_t>(std::count(active.begin(), active.end(), 1)); }

void keep_sampled_tiles(std::vector<std::uint32_t>& tiles, const SampledTiles& sampled) {
    std::erase_if(tiles, [&](std::uint32_t t) {
        const std::uint32_t x = t & 0xffffu, y = t >> 16;
        return t == kNoTile || x >= sampled.columns || y >= sampled.rows || !sampled.takes(x, y);
    });
    auto groups = tile_dispatch_groups(tiles.size());
    tiles.resize(std::size_t(groups[0]) * groups[1], kNoTile);
}

}  // namespace fg
