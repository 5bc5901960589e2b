// What happens to a shaded colour before display, shared by the post pass (the picture), the
// shade pass (its tone map, when the pack has no post effects) and the AOV pass (the HDR beauty).

#ifdef FG_HAS_FOG
// The fog's density at the ray origin ro (frame coordinates): fog_density at the fog's height,
// falling by e every 1 / falloff above it (height fog), the same everywhere without a falloff.
float fg_fog_density_at(vec3 ro)
{
    float k = fg_scene.fog_height.x;
    if (k <= 0.0) return fg_scene.fog_density;
#ifdef FG_DOUBLE_SCENE
    float y0 = float(double(ro.y) + fg_anchor().y);
#else
    float y0 = ro.y;
#endif
    return fg_scene.fog_density * exp(-k * (y0 - fg_scene.fog_height.y));
}

// The fog's optical depth along the ray from ro along the unit rd, over t: the density times t,
// and for height fog the density's exponential in height integrated in closed form,
// d0 (1 - e^(-k dy t)) / (k dy), its series where k dy t is small.
float fg_fog_depth(vec3 ro, vec3 rd, float t)
{
    float k = fg_scene.fog_height.x;
    if (k <= 0.0) return fg_scene.fog_density * t;
    float x = k * rd.y * t;
    float along = abs(x) < 1e-3 ? 1.0 - 0.5 * x + x * x / 6.0 : (1.0 - exp(-x)) / x;
    return fg_fog_density_at(ro) * t * along;
}
#endif

// The post effects the pack lists, and only those: scattering fog (homogeneous or height fog)
// along the ray from ro along rd, with the main light it scatters towards the eye (`scattered`,
// fg_fog_light in shading.glsl), glow from the closest approach along the ray (`closest`), the
// vignette. t < 0 is a miss.
vec3 fg_post_effects(vec3 color, ivec2 pixel, ivec2 size, vec3 ro, vec3 rd, float t, float closest, vec3 scattered)
{
#ifdef FG_HAS_GLOW
    color += fg_scene.glow_color * exp(-max(closest, 0.0) / fg_scene.glow_falloff);
#endif
#ifdef FG_HAS_FOG
    float distance_through = t < 0.0 ? fg_scene.far_limit : t;
    color = mix(fg_scene.fog_color, color, exp(-fg_fog_depth(ro, rd, distance_through))) + scattered;
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
