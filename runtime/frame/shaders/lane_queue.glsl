// Persistent lanes (Aila and Laine 2009, "Understanding the efficiency of ray traversal on GPUs"):
// a fixed number of workgroups loop, and lanes whose rays ended take the next pixels from a queue,
// so SIMD lanes do not idle while their group waits for the slowest ray. Each pixel's march is
// the same computation either way, so frames are bit-identical with and without.
//
// Work is handed out in 8x8 tiles, and in Morton order inside a tile, so the rays of one subgroup
// stay close together (coherent memory, similar step counts). One atomic per subgroup fetches work
// for every lane that needs it (ballot and prefix count), not one per lane.


layout(set = 0, binding = 13, std430) buffer FgLaneQueue { uint next[]; } fg_lane_queue;

// Whether a burst of marching goes on: while at least FG_LANE_BURST (a knob) of the subgroup's lanes (or
// all of those still working) have a ray. Lanes are refilled between bursts, all at once, rather
// than each as its ray ends: SIMD hardware that runs both sides of a branch under a mask (as
// llvmpipe does) would otherwise pay for a ray's setup and its stores in every step, and on GPUs it
// keeps the fetch, the setup and the stores coherent.
bool fg_lanes_burst(bool marching)
{
    uint marching_lanes = subgroupBallotBitCount(subgroupBallot(marching));
    uint lanes = subgroupBallotBitCount(subgroupBallot(true));
    uint share = max(1u, uint(ceil(float(gl_SubgroupSize) * FG_LANE_BURST)));
    return marching_lanes > 0u && marching_lanes >= min(lanes, share);
}

// The next work index for each lane with `need` (others get 0xffffffff), from queue word `slot`.
uint fg_take_work(bool need, uint slot)
{
    uvec4 ballot = subgroupBallot(need);
    uint wanted = subgroupBallotBitCount(ballot);
    if (wanted == 0u) return 0xffffffffu;
    uint base = 0u;
    if (subgroupElect()) base = atomicAdd(fg_lane_queue.next[slot], wanted);
    base = subgroupBroadcastFirst(base);
    return need ? base + subgroupBallotExclusiveBitCount(ballot) : 0xffffffffu;
}

// The cell of a grid `grid` cells wide and high that work index `index` stands for, tile by tile
// (8x8 cells, rows of tiles), Morton order inside a tile; (-1, -1) past the grid's end. A tile at
// the edge has cells outside the grid: the caller skips them.
ivec2 fg_work_cell(uint index, ivec2 grid)
{
    uint tiles_x = (uint(grid.x) + 7u) / 8u;
    uint tile = index >> 6u;
    uint m = index & 63u;
    uvec2 in_tile = uvec2((m & 1u) | ((m >> 1u) & 2u) | ((m >> 2u) & 4u), ((m >> 1u) & 1u) | ((m >> 2u) & 2u) | ((m >> 3u) & 4u));
    uvec2 cell = uvec2(tile % tiles_x, tile / tiles_x) * 8u + in_tile;
    if (tile / tiles_x >= (uint(grid.y) + 7u) / 8u) return ivec2(-1);
    return ivec2(cell);
}

// A lane without a ray takes the next cell of the queue (its dispatch's queue word: stride - 1).
// True, with its pixel, when the dispatch marches that pixel: in the grid, taken at this stride
// (fg_dispatch_takes), inside the lens (the resolve pass gives the others their miss). `dry` turns
// true once the queue runs out or the lane has taken its share (FG_LANE_PIXELS: llvmpipe's loop
// limit, gpu_interface.h); `taken` counts that share.
bool fg_lane_takes_pixel(int view, int stride, ivec2 grid, inout bool dry, inout uint taken, out ivec2 pixel)
{
    ivec2 cell = fg_work_cell(fg_take_work(true, uint(stride - 1)), grid);
    pixel = cell * stride;
    dry = cell.x < 0 || ++taken == FG_LANE_PIXELS;
    return cell.x >= 0 && cell.x < grid.x && cell.y < grid.y && fg_dispatch_takes(view, pixel, stride) &&
           !fg_outside_lens(view, pixel);
}
