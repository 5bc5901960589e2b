//! pass: post
//! needs: distance
//! when: any-effect fog glow vignette
//! include: post_effects.glsl
//! include: dispatch_tiles.glsl
// Post effects the pack lists, and only those (post_effects.glsl); then tonemapping into the final
// image. (Foveation has its own pass, fovea.comp, that runs after this one.)

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_depth;
layout(set = 0, binding = 4, rgba16f) uniform readonly image2D fg_color;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 5, r32f) uniform readonly image2D fg_glow;
#endif
layout(set = 0, binding = 6, rgba8) uniform writeonly image2D fg_final;
layout(push_constant) uniform FgPostPush { PostPush pc; };

void main()
{
    ivec2 pixel = fg_dispatch_cell(pc.stride, ivec2(gl_GlobalInvocationID.xy));
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, pixel)) {
        imageStore(fg_final, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        return;
    }
    vec3 color = imageLoad(fg_color, pixel).rgb;
    float t = imageLoad(fg_depth, pixel).x;
    float closest = 0.0;
#ifdef FG_HAS_GLOW
    closest = imageLoad(fg_glow, pixel).x;
#endif
    color = fg_post_effects(color, pixel, size, t, closest);
    // The fade (snap turns, the head in the surface) scales the displayed image linearly.
    imageStore(fg_final, pixel, vec4(fg_tonemap(color) * (1.0 - fg_scene.fade), 1.0));
}
