// What happens to a shaded colour before display, shared by the post pass (the picture), the
// shade pass (its tone map, when the pack has no post effects) and the AOV pass (the HDR beauty).

// The post effects the pack lists, and only those: homogeneous scattering fog, glow from the
// closest approach along the ray (`closest`), the vignette. t < 0 is a miss.
vec3 fg_post_effects(vec3 color, ivec2 pixel, ivec2 size, float t, float closest)
{
#ifdef FG_HAS_GLOW
    color += fg_scene.glow_color * exp(-max(closest, 0.0) / fg_scene.glow_falloff);
#endif
#ifdef FG_HAS_FOG
    float distance_through = t < 0.0 ? fg_scene.far_limit : t;
    color = mix(fg_scene.fog_color, color, exp(-fg_scene.fog_density * distance_through));
#endif
#ifdef FG_HAS_VIGNETTE
    // A comfort effect of the headset's frustum; a panorama has no edges to darken.
    if (fg_projection() == FG_PROJECTION_PERSPECTIVE) {
        vec2 q = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
        color *= 1.0 - fg_scene.vignette * smoothstep(0.3, 1.4, dot(q, q));
    }
#endif
    return color;
}

vec3 fg_tonemap(vec3 c)
{
    // ACES fit (Narkowicz): keeps bright glow from clipping to white abruptly.
    c *= fg_scene.exposure;
    return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}
