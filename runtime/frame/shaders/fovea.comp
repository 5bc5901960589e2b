//! pass: fovea
//! needs: nothing
//! when: always
//! include: dispatch_tiles.glsl
// Fixed foveation's fill. Beyond the fovea only one pixel of each 2x2 block, the even one, was
// marched and shaded (fg_dispatch_takes); this fills in the other three by bilinear interpolation between the marched
// pixels around them, and across the band between fovea and periphery blends the full-resolution
// image into the interpolated one, so no edge shows. Depth cannot be interpolated (hit or miss, and
// two surfaces at a silhouette): a filled pixel takes the nearest hit among the marched pixels its
// colour blends, a miss only where none of them hits. So a filled depth never lies behind the
// surfaces seen around it, which is what a compositor's reprojection and the accuracy counts take
// depth to mean (the block's own pixel alone put the background behind a foreground edge).
// Odd pixels of the periphery outside the lens get their miss and black here. Only odd pixels are
// written and only even ones read, so the pass can work in place.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform image2D fg_depth;
layout(set = 0, binding = 4, rgba8) uniform image2D fg_final;
layout(push_constant) uniform FgFoveaPush { FoveaPush pc; };

// The nearest hit among the marched corners lo, hi of a filled pixel's block that its colour blends
// (bilinear weight f; a corner of zero weight is not seen there); FG_MISS where none of them hits.
float fg_nearest_hit(ivec2 lo, ivec2 hi, vec2 f)
{
    float corners[4] = float[4](imageLoad(fg_depth, lo).x,
                                f.x > 0.0 ? imageLoad(fg_depth, ivec2(hi.x, lo.y)).x : FG_MISS,
                                f.y > 0.0 ? imageLoad(fg_depth, ivec2(lo.x, hi.y)).x : FG_MISS,
                                f.x > 0.0 && f.y > 0.0 ? imageLoad(fg_depth, hi).x : FG_MISS);
    float nearest = FG_MISS;
    for (int i = 0; i < 4; ++i)
        if (corners[i] >= 0.0 && (nearest < 0.0 || corners[i] < nearest)) nearest = corners[i];
    return nearest;
}

void main()
{
    ivec2 pixel = fg_dispatch_cell(1, ivec2(gl_GlobalInvocationID.xy));
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    if (((pixel.x | pixel.y) & 1) == 0) return;
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
    ivec2 lo = pixel & ~1;
    ivec2 hi = min(lo + 2, (size - 1) & ~1);
    vec2 f = vec2(pixel - lo) * 0.5;
    vec4 top = mix(imageLoad(fg_final, lo), imageLoad(fg_final, ivec2(hi.x, lo.y)), f.x);
    vec4 bottom = mix(imageLoad(fg_final, ivec2(lo.x, hi.y)), imageLoad(fg_final, hi), f.x);
    vec4 color = mix(top, bottom, f.y);
    if (s < 1.0)
        color = mix(imageLoad(fg_final, pixel), color, s);
    else
        imageStore(fg_depth, pixel, vec4(fg_nearest_hit(lo, hi, f)));
    imageStore(fg_final, pixel, color);
}
