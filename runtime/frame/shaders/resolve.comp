//! pass: resolve
//! needs: nothing
//! when: always
// After a marching pass with persistent lanes: each pixel's result, from the rays buffer
// (march_rays.glsl) into the view's depth, glow and level-0 atlas images, one invocation per pixel,
// so the image stores are coherent. Pixels outside the lens get their miss here; the pixels that
// foveation leaves to the fovea pass are left alone, as the marching pass leaves them.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform writeonly image2D fg_depth;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 4, r32f) uniform writeonly image2D fg_glow;
#endif
layout(set = 0, binding = 5, rg32f) uniform writeonly image2D fg_levels;   // written when pc.levels != 0
layout(set = 0, binding = 6, std430) readonly buffer FgRays { vec4 rays[]; } fg_rays;
layout(push_constant) uniform FgResolvePush { ResolvePush pc; };

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = fg_view_size(pc.view);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    vec4 ray;
    if (fg_outside_lens(pc.view, pixel)) {
        ray = vec4(FG_MISS, 0.0, 1e30, 0.0);   // as conemarch.comp: nothing proven where nothing was marched
    } else {
        bool periphery = fg_periphery(pc.view, pixel) >= 1.0;
        if (periphery && ((pixel.x | pixel.y) & 1) != 0) return;   // filled by the fovea pass
        ray = fg_rays.rays[pixel.y * size.x + pixel.x];
    }
    if (pc.levels != 0) imageStore(fg_levels, pixel, vec4(ray.x, ray.y, 0.0, 0.0));
    imageStore(fg_depth, pixel, vec4(ray.x));
#ifdef FG_HAS_GLOW
    imageStore(fg_glow, pixel, vec4(ray.z));
#endif
}
