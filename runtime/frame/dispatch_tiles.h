#pragma once
// Which 8x8 tiles of its grid an eye's pass dispatches: only those holding pixels the pass takes
// (shaders/dispatch_tiles.glsl maps each workgroup to its tile). llvmpipe runs every line of a
// shader for a SIMD group whose lanes all return at once, so the fovea's passes would otherwise pay
// for the periphery's pixels, the periphery's for the fovea's, and every pass for the pixels the
// lens hides (little: their loops run once; docs/accuracy.md measures 1 %).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu_uniforms.h"

namespace fg {

enum class TileRegion {
    Fovea,         // full resolution: the pixels short of the periphery (fg_periphery < 1)
    FoveaLevel1,   // conemarch level 1's cells over those pixels
    Periphery,     // the periphery's grid (one invocation per 2x2 block): even pixels with fg_periphery >= 1
    Fill,          // 2x2 blocks holding pixels the fovea pass fills or blends (fg_periphery > 0)
    Whole,         // full resolution, every pixel: an eye without foveation
};

// Whether a list leaves out the tiles wholly outside the lens. Its passes write those pixels' miss
// and black, the same every frame, so once every image (both versions of a history image) holds
// them a list may leave them out (FrameExecutor: for as long as the lens stays put).
enum class OutsideLens { Listed, Left };

const char* tile_region_name(TileRegion region);

// A list is dispatched as rows of at most kTileRow workgroups (the least maxComputeWorkGroupCount
// Vulkan allows; an 8K eye has 524,288 tiles), its last row padded with kNoTile, which the shaders'
// bounds checks skip.
inline constexpr std::uint32_t kTileRow = 65535;
inline constexpr std::uint32_t kNoTile = 0xffffffffu;

// The workgroups that dispatch a list of this many tiles.
std::array<std::uint32_t, 3> tile_dispatch_groups(std::size_t tiles);

// The tiles, each packed as x | y << 16 in units of 8 cells of the region's grid, in rows. A tile
// is listed when one of its pixels may be taken (a pixel's margin against float rounding): a
// superset of what the shader decides per pixel (fg_dispatch_takes, and with OutsideLens::Left
// fg_outside_lens), never a subset.
std::vector<std::uint32_t> list_dispatch_tiles(const GpuFrame& frame, int view, TileRegion region,
                                               OutsideLens outside = OutsideLens::Listed);

// The 8x8-pixel tiles of an eye's full-resolution grid that still take samples (adaptive sampling:
// a tile whose pixels have converged is left out of the eye's full-resolution passes).
struct SampledTiles {
    std::uint32_t columns = 0, rows = 0;     // tiles across and down: the eye's size / 8, rounded up
    std::vector<std::uint8_t> active;        // 1: the tile takes the next sample; row by row
    SampledTiles() = default;
    SampledTiles(std::uint32_t width, std::uint32_t height)
        : columns((width + 7) / 8), rows((height + 7) / 8), active(std::size_t(columns) * rows, 1) {}
    bool takes(std::uint32_t tile_x, std::uint32_t tile_y) const { return active[std::size_t(tile_y) * columns + tile_x] != 0; }
    std::size_t count() const;
};

// A list of full-resolution tiles (TileRegion::Whole or Fovea) without the tiles `sampled` leaves
// out, padded again to whole rows.
void keep_sampled_tiles(std::vector<std::uint32_t>& tiles, const SampledTiles& sampled);

// How many entries a list of the region's grid has at most, padding included (the buffer that holds it).
std::uint32_t dispatch_tile_capacity(std::uint32_t width, std::uint32_t height, TileRegion region);

}  // namespace fg
