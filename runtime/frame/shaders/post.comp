//! pass: post
//! needs: distance
//! when: any-effect fog glow vignette
// Post effects the pack lists, and only those: homogeneous scattering fog, glow from the closest
// approach along the ray, the vignette; then tonemapping into the final image. (Foveation has
// its own pass, fovea.comp, that runs after this one.)

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_depth;
layout(set = 0, binding = 4, rgba16f) uniform readonly image2D fg_color;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 5, r32f) uniform readonly image2D fg_glow;
#endif
layout(set = 0, binding = 6, rgba8) uniform writeonly image2D fg_final;
layout(push_constant) uniform FgPostPush { PostPush pc; };

vec3 fg_tonemap(vec3 c)
{
    c *= fg_scene.exposure;
    return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * pc.stride;
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, pixel)) {
        imageStore(fg_final, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        return;
    }
    vec3 color = imageLoad(fg_color, pixel).rgb;
    float t = imageLoad(fg_depth, pixel).x;
#ifdef FG_HAS_GLOW
    float closest = imageLoad(fg_glow, pixel).x;
    color += fg_scene.glow_color * exp(-max(closest, 0.0) / fg_scene.glow_falloff);
#endif
#ifdef FG_HAS_FOG
    float distance_through = t < 0.0 ? fg_scene.far_limit : t;
    color = mix(fg_scene.fog_color, color, exp(-fg_scene.fog_density * distance_through));
#endif
#ifdef FG_HAS_VIGNETTE
    // A comfort effect of the headset's frustum; a panorama has no edges to darken.
    if (fg_frame.projection == FG_PROJECTION_PERSPECTIVE) {
        vec2 q = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
        color *= 1.0 - fg_scene.vignette * smoothstep(0.3, 1.4, dot(q, q));
    }
#endif
    // The fade (snap turns, the head in the surface) scales the displayed image linearly.
    imageStore(fg_final, pixel, vec4(fg_tonemap(color) * (1.0 - fg_scene.fade), 1.0));
}
