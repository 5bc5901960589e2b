// Persistent lanes (Aila and Laine 2009, "Understanding the efficiency of ray traversal on GPUs"):
// a fixed number of workgroups loop, and each lane takes the next pixel from a queue as soon as its
// ray ends, so no SIMD lane idles while its group waits for the slowest ray. Each pixel's march is
// the same computation either way, so frames are bit-identical with and without.
//
// Work is handed out in 8x8 tiles, and in Morton order inside a tile, so the rays of one subgroup
// stay close together (coherent memory, similar step counts). One atomic per subgroup fetches work
// for every lane that needs it (ballot and prefix count), not one per lane.

layout(set = 0, binding = 13, std430) buffer FgLaneQueue { uint next[]; } fg_lane_queue;

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
