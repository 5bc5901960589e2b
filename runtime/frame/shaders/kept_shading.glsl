// A hit's shading as the shade pass keeps it for shading reuse (across the eyes, across frames): the
// colour without the terms that read the direction to the camera, the albedo those terms scale, and
// how often the colour was taken already. A taken colour gets its view terms recomputed for the
// viewer at hand (fg_scene_view_terms: the gallery's fake AO, stepped towards the camera, costs one
// evaluation where the whole shading costs three), so only the view-independent part travels.
// Pasted after the scene's functions and shading.glsl.

// The graph's albedo, diffuse, emission, shadow or specular read the view, or it reflects (the
// environment in its specular lobe too) or refracts: a colour shaded elsewhere cannot be split into
// a part that travels and scalar terms to recompute, so every hit is shaded.
#if defined(FG_OUT_ALBEDO_READS_VIEW) || defined(FG_OUT_DIFFUSE_READS_VIEW) || defined(FG_OUT_EMISSION_READS_VIEW) || \
    defined(FG_OUT_SHADOW_READS_VIEW) || defined(FG_OUT_SPECULAR_READS_VIEW) || defined(FG_HAS_REFLECTION) || \
    defined(FG_HAS_REFRACTION) || (defined(FG_HAS_ENVIRONMENT) && defined(FG_OUT_SPECULAR_COLOR))
const bool kShadingTravels = false;
#else
const bool kShadingTravels = true;
#endif
#if defined(FG_OUT_AO_READS_VIEW) || defined(FG_OUT_SSS_READS_VIEW) || defined(FG_OUT_RIM_READS_VIEW)
const bool kHasViewTerms = true;
#else
const bool kHasViewTerms = false;
#endif

struct FgKeptShading {
    vec3 base;     // linear colour before post effects, without the view terms
    vec3 albedo;
    float age;     // times taken since it was shaded
};

// What the terms that read the view add to a hit's colour, as fg_shade_hit adds them.
vec3 fg_view_color(FgSurface s, vec3 albedo)
{
    vec3 color = vec3(0.0);
#ifdef FG_OUT_AO_READS_VIEW
    color += albedo * fg_scene.ambient.rgb * s.ao;
#endif
#if defined(FG_OUT_SSS_READS_VIEW) && defined(FG_HAS_SSS)
    color += s.sss * fg_scene.sss_color.rgb * albedo;
#endif
#if defined(FG_OUT_RIM_READS_VIEW) && defined(FG_HAS_RIM)
    color += s.rim * fg_scene.rim_color.rgb;
#endif
    return color;
}

FgKeptShading fg_keep_shading(FgShading shading)
{
    return FgKeptShading(shading.color - fg_view_color(shading.surface, shading.albedo), shading.albedo, 0.0);
}

// The colour of a kept shading at the hit p seen along rd (normal n, where the view terms need one).
vec3 fg_kept_color(FgKeptShading kept, vec3 p, vec3 rd, vec3 n)
{
    if (!kHasViewTerms) return kept.base;
    return kept.base + fg_view_color(fg_scene_view_terms(p, -rd, n), kept.albedo);
}

// Seven halves in one rgba32ui texel.
uvec4 fg_pack_kept(FgKeptShading k)
{
    return uvec4(packHalf2x16(k.base.rg), packHalf2x16(vec2(k.base.b, k.albedo.r)), packHalf2x16(k.albedo.gb),
                 packHalf2x16(vec2(k.age, 0.0)));
}

FgKeptShading fg_unpack_kept(uvec4 u)
{
    vec2 a = unpackHalf2x16(u.x), b = unpackHalf2x16(u.y), c = unpackHalf2x16(u.z);
    return FgKeptShading(vec3(a, b.x), vec3(b.y, c), unpackHalf2x16(u.w).x);
}
