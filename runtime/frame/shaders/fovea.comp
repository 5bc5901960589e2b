//! pass: fovea
//! needs: nothing
//! when: always
//! include: dispatch_tiles.glsl
// Fixed foveation's fill. Beyond the fovea only one pixel of each 2x2 block, the even one, was
// marched and shaded (fg_dispatch_takes); this fills in the other three by bilinear interpolation
// (in linear light) between the marched pixels around them, and across the band between fovea and periphery blends the full-resolution
// image into the interpolated one, so no edge shows. Depth cannot be interpolated (hit or miss, and
// two surfaces at a silhouette): a filled pixel takes the nearest hit among the marched pixels its
// colour blends, a miss only where none of them hits. So a filled depth never lies behind the
// surfaces seen around it, which is what a compositor's reprojection and the accuracy counts take
// depth to mean (the block's own pixel alone put the background behind a foreground edge).
// Odd pixels of the periphery outside the lens get their miss and black here. Only odd pixels are
// written and only even ones read (besides each odd pixel's own), so the pass can work in place.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform image2D fg_depth;
layout(set = 0, binding = 4, rgba8) uniform image2D fg_final;
layout(push_constant) uniform FgFoveaPush { FoveaPush pc; };

// The nearest hit among a filled pixel's marched corners that its colour blends (bilinear weight f;
// a corner of zero weight is not seen there); FG_MISS where none of them hits.
float fg_nearest_hit(vec4 corners, vec2 f)
{
    if (f.x <= 0.0) corners.yw = vec2(FG_MISS);
    if (f.y <= 0.0) corners.zw = vec2(FG_MISS);
    float nearest = FG_MISS;
    for (int i = 0; i < 4; ++i)
        if (corners[i] >= 0.0 && (nearest < 0.0 || corners[i] < nearest)) nearest = corners[i];
    return nearest;
}

// Fills the odd pixel lo + offset of a block from its marched corners (colours c: lo, (hi.x, lo.y),
// (lo.x, hi.y), hi; their depths d).
void fg_fill(ivec2 lo, ivec2 offset, vec4 c[4], vec4 d)
{
    ivec2 pixel = lo + offset;
    if (any(greaterThanEqual(pixel, ivec2(fg_frame.eye_size)))) return;
    float s = fg_periphery(pc.view, pixel);
    if (s <= 0.0) return;
    if (fg_outside_lens(pc.view, pixel)) {
        // No dispatch of the periphery reaches an odd pixel: its miss is written here (in the band
        // the full-resolution passes wrote it).
        if (s >= 1.0) {
            imageStore(fg_depth, pixel, vec4(FG_MISS));
            imageStore(fg_final, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        }
        return;
    }
    vec2 f = vec2(offset) * 0.5;
    vec3 color = mix(mix(c[0].rgb, c[1].rgb, f.x), mix(c[2].rgb, c[3].rgb, f.x), f.y);
    if (s < 1.0)
        color = mix(fg_srgb_to_linear(imageLoad(fg_final, pixel).rgb), color, s);
    else
        imageStore(fg_depth, pixel, vec4(fg_nearest_hit(d, f)));
    imageStore(fg_final, pixel, vec4(fg_linear_to_srgb(color), 1.0));
}

// One invocation fills a 2x2 block's three odd pixels: its four corners are loaded once for all
// three (an invocation per pixel loaded them three times, and on llvmpipe the even pixel's lane ran
// the whole shader under a mask).
void main()
{
    ivec2 lo = fg_dispatch_cell(2, ivec2(gl_GlobalInvocationID.xy));
    ivec2 size = ivec2(fg_frame.eye_size);
    if (lo.x >= size.x || lo.y >= size.y) return;
    ivec2 hi = min(lo + 2, (size - 1) & ~1);
    ivec2 corner[4] = ivec2[4](lo, ivec2(hi.x, lo.y), ivec2(lo.x, hi.y), hi);
    vec4 c[4];
    vec4 d;
    for (int i = 0; i < 4; ++i) {
        c[i] = vec4(fg_srgb_to_linear(imageLoad(fg_final, corner[i]).rgb), 1.0);
        d[i] = imageLoad(fg_depth, corner[i]).x;
    }
    fg_fill(lo, ivec2(1, 0), c, d);
    fg_fill(lo, ivec2(0, 1), c, d);
    fg_fill(lo, ivec2(1, 1), c, d);
}
