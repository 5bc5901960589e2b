//! pass: fovea
//! needs: nothing
//! when: always
//! include: dispatch_tiles.glsl
// Fixed foveation's fill. Beyond the fovea only one pixel of each 2x2 block, the even one, was
// marched and shaded (fg_dispatch_takes); this fills in the other three by bilinear interpolation between the marched
// pixels around them, and across the band between fovea and periphery blends the full-resolution
// image into the interpolated one, so no edge shows. Depth takes the block's marched pixel: hit or
// miss cannot be interpolated; odd pixels of the periphery outside the lens get their miss and black
// here. Only odd pixels are written and only even ones read, so the pass can work in place.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform image2D fg_depth;
layout(set = 0, binding = 4, rgba8) uniform image2D fg_final;
layout(push_constant) uniform FgFoveaPush { FoveaPush pc; };

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
        imageStore(fg_depth, pixel, imageLoad(fg_depth, lo));
    imageStore(fg_final, pixel, color);
}
