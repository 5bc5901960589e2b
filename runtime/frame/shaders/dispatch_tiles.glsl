// An eye's pass dispatches only the 8x8 tiles of its grid that hold pixels it takes
// (FG_SPEC_TILE_LIST): the runtime lists them (dispatch_tiles.cpp), one workgroup per tile, and the
// shader still decides each pixel (fg_dispatch_takes, fg_outside_lens). llvmpipe runs every line of
// a shader for a SIMD group whose lanes all return at once, so a dispatch over the whole image would
// pay for the periphery's pixels in the fovea's passes, for the fovea's in the periphery's, and for
// the pixels the lens hides.

// Tiles as x | y << 16, in units of 8 cells of the pass's grid, in rows of workgroups (bound either
// way). Padding (0xffffffff) maps past every image.
layout(set = 0, binding = 16, std430) readonly buffer FgTiles { uint fg_tiles[]; };

// The cell of its grid an invocation stands for, from its cell of the dispatch grid (8x8
// workgroups: the executor checks), and the pixel at `stride` pixels per cell.
ivec2 fg_dispatch_cell(int stride, ivec2 cell)
{
    if (FG_SPEC_TILE_LIST != 1) return cell * stride;
    uint tile = fg_tiles[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x];
    ivec2 in_tile = cell - ivec2(gl_WorkGroupID.xy) * 8;
    return (ivec2(tile & 0xffffu, tile >> 16u) * 8 + in_tile) * stride;
}
