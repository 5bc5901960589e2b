// The environment (scene.environment): a lat-long HDR image around the scene, or a uniform sky, as
// the runtime lays it out in one buffer (frame/environment_light.h). It is seen where rays miss and
// in reflections; it lights the surface diffusely, by its irradiance in spherical harmonics in a
// frame, and by directions drawn in proportion to its brightness while samples accumulate; a
// specular lobe reflects it prefiltered by the lobe in a frame (environment_gloss.h).
#ifdef FG_HAS_ENVIRONMENT
layout(set = 0, binding = 17, std430) readonly buffer FgEnvironment { uint fg_env[]; };

const uint FG_ENV_HARMONICS = 4u;
const uint FG_ENV_TABLES = 40u;

uint fg_env_width() { return fg_env[0]; }
uint fg_env_height() { return fg_env[1]; }
float fg_env_float(uint at) { return uintBitsToFloat(fg_env[at]); }
uint fg_env_row_table(uint row) { return FG_ENV_TABLES + fg_env_height() + 1u + row * (fg_env_width() + 1u); }
uint fg_env_texels() { return fg_env_row_table(fg_env_height()); }

// A world direction in the image's frame, and back: the image turns about +y by environment.w.
vec3 fg_env_local(vec3 d)
{
    float c = cos(fg_scene.environment.w), s = sin(fg_scene.environment.w);
    return vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}
vec3 fg_env_world(vec3 l)
{
    float c = cos(fg_scene.environment.w), s = sin(fg_scene.environment.w);
    return vec3(c * l.x + s * l.z, l.y, -s * l.x + c * l.z);
}

// The image's point (u, v) of a direction in its frame: v = 0 straight up, u = 0.5 looking down -z,
// growing towards +x (fgplay's equirectangular panoramas).
vec2 fg_env_uv(vec3 l)
{
    return vec2(0.5 + atan(l.x, -l.z) * (0.5 / FG_FLOAT_PI), acos(clamp(l.y, -1.0, 1.0)) * (1.0 / FG_FLOAT_PI));
}

// Texel (i, j) of the image of width w whose texels start at word `first`.
vec3 fg_env_texel(uint first, uint w, uint i, uint j)
{
    uint at = first + 2u * (j * w + i);
    return vec3(unpackHalf2x16(fg_env[at]), unpackHalf2x16(fg_env[at + 1u]).x);
}

// The lat-long image of w x h texels from word `first`, filtered bilinearly at direction l of its
// frame (wrapping around, clamped at the poles).
vec3 fg_env_bilinear(uint first, uint w, uint h, vec3 l)
{
    vec2 at = fg_env_uv(l) * vec2(w, h) - 0.5;
    vec2 base = floor(at), f = at - base;
    uint i0 = uint(int(base.x) + int(w)) % w, i1 = (i0 + 1u) % w;
    uint j0 = uint(clamp(int(base.y), 0, int(h) - 1)), j1 = uint(clamp(int(base.y) + 1, 0, int(h) - 1));
    vec3 top = mix(fg_env_texel(first, w, i0, j0), fg_env_texel(first, w, i1, j0), f.x);
    vec3 bottom = mix(fg_env_texel(first, w, i0, j1), fg_env_texel(first, w, i1, j1), f.x);
    return mix(top, bottom, f.y);
}

// The radiance arriving from world direction d: the image, times the scene's colour and intensity.
vec3 fg_environment_radiance(vec3 d)
{
    return fg_scene.environment.rgb * fg_env_bilinear(fg_env_texels(), fg_env_width(), fg_env_height(), fg_env_local(d));
}

#ifdef FG_OUT_SPECULAR_COLOR
// The specular lobe's section (environment_gloss.h): its table and the prefiltered levels.
const uint FG_ENV_GLOSS_TABLE = 32u;
const uint FG_ENV_GLOSS_LEVELS = 5u;

vec2 fg_env_gloss_entry(uint i, uint j)
{
    uint at = fg_env[2] + 2u * (j * FG_ENV_GLOSS_TABLE + i);
    return vec2(fg_env_float(at), fg_env_float(at + 1u));
}

// (A, B) of the table at a cosine between normal and view and a roughness, filtered bilinearly: a
// white sky reflects F0 * A + B.
vec2 fg_environment_gloss_scale(float cos_view, float roughness)
{
    float last = float(FG_ENV_GLOSS_TABLE - 1u);
    vec2 at = clamp(vec2(cos_view, roughness) * float(FG_ENV_GLOSS_TABLE) - 0.5, vec2(0.0), vec2(last));
    uvec2 i0 = uvec2(at), i1 = min(i0 + 1u, uvec2(FG_ENV_GLOSS_TABLE - 1u));
    vec2 f = at - vec2(i0);
    return mix(mix(fg_env_gloss_entry(i0.x, i0.y), fg_env_gloss_entry(i1.x, i0.y), f.x),
               mix(fg_env_gloss_entry(i0.x, i1.y), fg_env_gloss_entry(i1.x, i1.y), f.x), f.y);
}

// Prefiltered level k (0 the image itself, k the lobe of roughness 0.2 k) at direction l of the
// image's frame.
vec3 fg_env_gloss_level(uint k, vec3 l)
{
    if (k == 0u) return fg_env_bilinear(fg_env_texels(), fg_env_width(), fg_env_height(), l);
    uint header = fg_env[2] + 2u * FG_ENV_GLOSS_TABLE * FG_ENV_GLOSS_TABLE + 4u * (k - 1u);
    return fg_env_bilinear(fg_env[header + 2u], fg_env[header], fg_env[header + 1u], l);
}

// The radiance a lobe of this roughness gathers about world direction d (the mirror direction),
// between the two nearest prefiltered levels.
vec3 fg_environment_prefiltered(vec3 d, float roughness)
{
    vec3 l = fg_env_local(d);
    float at = clamp(roughness, 0.0, 1.0) * float(FG_ENV_GLOSS_LEVELS);
    uint k = min(uint(at), FG_ENV_GLOSS_LEVELS - 1u);
    return fg_scene.environment.rgb * mix(fg_env_gloss_level(k, l), fg_env_gloss_level(k + 1u, l), at - float(k));
}
#endif

// The environment's nine harmonics at world direction d, band l weighted by weight[l]. The runtime
// stores the radiance's harmonics convolved with the clamped cosine (1, 2/3 and 1/4 per band).
vec3 fg_environment_harmonics(vec3 d, vec3 weight)
{
    vec3 l = fg_env_local(d);
    float y[9] = float[9](0.282095, 0.488603 * l.y, 0.488603 * l.z, 0.488603 * l.x, 1.092548 * l.x * l.y,
                          1.092548 * l.y * l.z, 0.315392 * (3.0 * l.z * l.z - 1.0), 1.092548 * l.x * l.z,
                          0.546274 * (l.x * l.x - l.y * l.y));
    vec3 e = vec3(0.0);
    for (uint k = 0u; k < 9u; k++) {
        uint at = FG_ENV_HARMONICS + 4u * k;
        e += (k == 0u ? weight.x : k < 4u ? weight.y : weight.z) * y[k] *
             vec3(fg_env_float(at), fg_env_float(at + 1u), fg_env_float(at + 2u));
    }
    return fg_scene.environment.rgb * max(e, vec3(0.0));
}

// What a white diffuse surface facing n reflects of the environment, unshadowed: its irradiance
// over pi, from the nine harmonics.
vec3 fg_environment_irradiance(vec3 n)
{
    return fg_environment_harmonics(n, vec3(1.0));
}

// The environment's light a medium of Henyey-Greenstein anisotropy g scatters towards the eye
// looking along d, unshadowed: the phase's Legendre weights are g^l, so each band of the radiance
// (the stored bands undone from the cosine's) is weighted by g^l (Funk-Hecke).
vec3 fg_environment_scattered(vec3 d, float g)
{
    return fg_environment_harmonics(d, vec3(1.0, 1.5 * g, 4.0 * g * g));
}

// The interval of a cumulative table (count intervals from `first`) that x falls in.
uint fg_env_search(uint first, uint count, float x)
{
    uint lo = 0u, hi = count - 1u;
    while (lo < hi) {
        uint mid = (lo + hi + 1u) / 2u;
        if (fg_env_float(first + mid) <= x) lo = mid;
        else hi = mid - 1u;
    }
    return lo;
}

// The density, per unit solid angle, with which fg_environment_sample draws world direction d: its
// texel's share of the brightness over the texel's solid angle at d.
float fg_environment_pdf(vec3 d)
{
    vec3 l = fg_env_local(d);
    vec2 uv = fg_env_uv(l);
    uint w = fg_env_width(), h = fg_env_height();
    uint i = min(uint(uv.x * float(w)), w - 1u), j = min(uint(uv.y * float(h)), h - 1u);
    float row = fg_env_float(FG_ENV_TABLES + j + 1u) - fg_env_float(FG_ENV_TABLES + j);
    uint table = fg_env_row_table(j);
    float column = fg_env_float(table + i + 1u) - fg_env_float(table + i);
    float sin_theta = max(sqrt(max(1.0 - l.y * l.y, 0.0)), 1e-6);
    return row * column * float(w * h) / (2.0 * FG_FLOAT_PI * FG_FLOAT_PI * sin_theta);
}

// A world direction drawn in proportion to the image's brightness times sin(theta), from xi in
// [0, 1)^2: a row by the rows' table, a column by the row's, uniformly within the texel.
vec3 fg_environment_sample(vec2 xi)
{
    uint w = fg_env_width(), h = fg_env_height();
    uint j = fg_env_search(FG_ENV_TABLES, h, xi.y);
    float r0 = fg_env_float(FG_ENV_TABLES + j), r1 = fg_env_float(FG_ENV_TABLES + j + 1u);
    float v = (float(j) + clamp((xi.y - r0) / max(r1 - r0, 1e-30), 0.0, 1.0)) / float(h);
    uint table = fg_env_row_table(j);
    uint i = fg_env_search(table, w, xi.x);
    float c0 = fg_env_float(table + i), c1 = fg_env_float(table + i + 1u);
    float u = (float(i) + clamp((xi.x - c0) / max(c1 - c0, 1e-30), 0.0, 1.0)) / float(w);
    float theta = v * FG_FLOAT_PI, phi = (u - 0.5) * 2.0 * FG_FLOAT_PI;
    return fg_env_world(vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi)));
}
#endif
