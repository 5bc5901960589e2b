// Shared by every pass: the frame and scene uniforms, ray generation and the march helpers.
// The compiler pastes this after the knob constants and before the scene's code.

// Pi as the passes' float: the scene's FG_PI is a double in packs of precision "double".
const float FG_FLOAT_PI = 3.14159265;

// The frame and scene blocks: their structs are in gpu_interface.h, pasted before this file.
layout(set = 0, binding = 0, std140) uniform FgFrame { GpuFrame fg_frame; };
layout(set = 0, binding = 1, std140) uniform FgScene { GpuScene fg_scene; };

#ifdef FG_DOUBLE_SCENE
dvec3 fg_anchor()
{
    return dvec3(fg_frame.anchor_hi.xyz) + dvec3(fg_frame.anchor_lo.xyz);
}
#endif

// The scene bounds' centre in the frame's coordinates (relative to the anchor in double packs).
vec3 fg_bounds_centre()
{
#ifdef FG_DOUBLE_SCENE
    return vec3((dvec3(fg_scene.bounds_centre) + dvec3(fg_scene.bounds_centre_lo)) - fg_anchor());
#else
    return fg_scene.bounds_centre;
#endif
}

// How a pixel becomes a ray (fg_projection(), the same for every pass of a frame): the view's
// perspective frustum (the headset), or offline panoramas: equirectangular around the view's
// origin, and omni-directional stereo (ODS), where each column's eye sits on the circle of the
// interpupillary distance, looking along the tangent, as 360-degree stereo video players expect.

// The frame's projection: a dispatch constant where the runtime fixed it (the code of the other
// projections is then dropped; a CPU rasteriser would run it all), else the frame's field.
uint fg_projection()
{
    return FG_SPEC_PROJECTION >= 0 ? uint(FG_SPEC_PROJECTION) : fg_frame.projection;
}

// Longitude (0 straight ahead, positive to the right) and latitude (positive up) of a panorama's
// uv in [0, 1]^2, y down.
vec2 fg_panorama_angles(vec2 uv)
{
    return vec2((uv.x - 0.5) * 6.28318531, (0.5 - uv.y) * 3.14159265);
}

// A panorama's point uv moved by the frame's sub-pixel jitter (GpuFrame.jitter). A perspective
// frame carries its jitter in the frustum (stereo_rig.h: jittered()), where every pass that
// projects points back into the image finds it.
vec2 fg_panorama_uv(int view, vec2 uv)
{
    return uv + fg_frame.jitter.xy / vec2(view == FG_VIEW_CENTRE ? fg_frame.centre_size : fg_frame.eye_size);
}

// Ray direction through a point of a view's image, uv in [0, 1]^2 with y down.
vec3 fg_ray_dir(int view, vec2 uv)
{
    GpuView v = fg_frame.views[view];
    if (fg_projection() != FG_PROJECTION_PERSPECTIVE) {
        vec2 a = fg_panorama_angles(fg_panorama_uv(view, uv));
        return cos(a.y) * (sin(a.x) * v.right.xyz + cos(a.x) * v.forward.xyz) + sin(a.y) * v.up.xyz;
    }
    float tx = mix(v.tan_fov.x, v.tan_fov.y, uv.x);
    float ty = mix(v.tan_fov.w, v.tan_fov.z, uv.y);
    return normalize(v.forward.xyz + tx * v.right.xyz + ty * v.up.xyz);
}

// The share of the IPD an ODS eye keeps at latitude `lat` (gpu_interface.h).
float fg_ods_separation(float lat)
{
    return 1.0 - smoothstep(0.0, 1.0, (abs(lat) - FG_ODS_FADE_START) / FG_ODS_FADE_WIDTH);
}

// Ray origin of a pixel: the view's eye, except in ODS, where the left (view 0) and right eye
// (view 1) of each column sit half the IPD to either side of the head, across that column's
// direction (the views' origins are the head's centre then), closer together towards the poles.
vec3 fg_ray_origin(int view, vec2 uv)
{
    GpuView v = fg_frame.views[view];
    if (fg_projection() == FG_PROJECTION_ODS && view != FG_VIEW_CENTRE) {
        vec2 a = fg_panorama_angles(fg_panorama_uv(view, uv));
        float side = (view == FG_VIEW_LEFT ? -0.5 : 0.5) * fg_ods_separation(a.y);
        return v.origin.xyz + side * fg_frame.ipd * (cos(a.x) * v.right.xyz - sin(a.x) * v.forward.xyz);
    }
    return v.origin.xyz;
}

// The interval [near, far] of distances along a ray where it can meet the scene bounds (a sphere),
// clipped to the far limit. With cone_tan > 0 the interval covers every ray of the cone of that
// half-angle around rd: the cone must point at the sphere, and any point of the sphere is between
// |c - ro| - r and |c - ro| + r from the origin. Empty when near > far. With spread > 0 it also
// covers rays starting up to that far from ro (fg_origin_spread): the sphere grows by as much.
vec2 fg_bounds_interval_spread(vec3 ro, vec3 rd, float cone_tan, float spread)
{
    vec3 oc = fg_bounds_centre() - ro;
    float radius = fg_scene.bounds_radius + spread;
    float far = fg_scene.far_limit;
    if (cone_tan > 0.0) {
        float dist = length(oc);
        if (dist > radius) {
            float to_centre = acos(clamp(dot(oc, rd) / dist, -1.0, 1.0));
            if (to_centre > atan(cone_tan) + asin(radius / dist)) return vec2(1.0, 0.0);
        }
        return vec2(max(dist - radius, 0.0), min(dist + radius, far));
    }
    float b = dot(oc, rd);
    float h = b * b - (dot(oc, oc) - radius * radius);
    if (h < 0.0) return vec2(1.0, 0.0);
    h = sqrt(h);
    return vec2(max(b - h, 0.0), min(b + h, far));
}

vec2 fg_bounds_interval(vec3 ro, vec3 rd, float cone_tan)
{
    return fg_bounds_interval_spread(ro, rd, cone_tan, 0.0);
}

// tan of the half-angle of the cone through a pixel 2^level full-resolution pixels wide. The
// half-diagonal in the tangent plane bounds the angle from above, so the cone covers the pixel.
float fg_cone_tan(int level)
{
    return tan(min(fg_frame.pixel_cone_tan * float(1 << level), 1.5));
}

ivec2 fg_view_size(int view)
{
    return ivec2(view == FG_VIEW_CENTRE ? fg_frame.centre_size : fg_frame.eye_size);
}

// How far the eyes of a conemarch block 2^level pixels wide sit from the eye of its centre pixel:
// 0 but in ODS, where the eye moves along the IPD circle by at most the arc of half the block's
// longitude, and towards the centre by as much as the pole fade changes over half its latitude
// (a smoothstep's slope is at most 1.5 per fade width). A cone whose radius grows by this much
// covers the rays of every eye.
float fg_origin_spread(int view, int level)
{
    if (fg_projection() != FG_PROJECTION_ODS || view == FG_VIEW_CENTRE) return 0.0;
    vec2 size = vec2(fg_view_size(view));
    float along = 3.14159265 * float(1 << level) / size.x;
    float across = 1.5 / FG_ODS_FADE_WIDTH * 0.5 * 3.14159265 * float(1 << level) / size.y;
    return 0.5 * fg_frame.ipd * (along + across);
}

// Conemarch levels live in one atlas image per view: level 0 at the origin, level k >= 1 stacked in
// a column to its right. Returns (origin.xy, size.xy) of a level.
ivec4 fg_level_rect(int level, ivec2 full)
{
    if (level == 0) return ivec4(0, 0, full);
    int y = 0;
    for (int k = 1; k < level; ++k) y += (full.y + (1 << k) - 1) >> k;
    ivec2 size = (full + ivec2((1 << level) - 1)) >> level;
    return ivec4(full.x, y, size);
}

// The grid cell (pixel, or block of a coarse level) of this invocation of an 8x8 workgroup. Each
// run of 8 consecutive invocations (one SIMD group on llvmpipe's 8 lanes, a quarter of a 32-lane
// warp) takes a 4x2 block rather than a row of 8: its rays stay closer together, so fewer lanes
// wait for the group's slowest ray (filled bulb 192², level 0's lanes busy 0.66 -> 0.73).
ivec2 fg_invocation_cell()
{
    uint lane = gl_LocalInvocationIndex & 7u, group = gl_LocalInvocationIndex >> 3u;
    uvec2 in_group = uvec2((group & 1u) * 4u + (lane & 3u), (group >> 1u) * 2u + (lane >> 2u));
    return ivec2(gl_WorkGroupID.xy * 8u + in_group);
}

// A miss in a depth image. Depths are distances along the ray, never NaN or infinite.
#define FG_MISS (-1.0)

// The lens mask (seed 001's "iris"): a pixel whose footprint lies wholly outside the ellipse the
// headset's lens shows is never marched or shaded. `margin` (uv) widens the ellipse by a coarse
// footprint, so a coarse level skips a block only if every child pixel skips too.
bool fg_outside_lens(int view, vec2 uv, vec2 margin)
{
    if (FG_SPEC_LENS == 0) return false;
    GpuView v = fg_frame.views[view];
    if (v.lens_radii.x <= 0.0) return false;
    vec2 q = (uv - v.lens_centre) / (v.lens_radii + margin);
    return dot(q, q) > 1.0;
}

bool fg_outside_lens(int view, ivec2 pixel)
{
    return fg_outside_lens(view, (vec2(pixel) + 0.5) / vec2(fg_view_size(view)), vec2(0.0));
}

// The centre eye of stereo reprojection is never foveated.
bool fg_foveated(int view)
{
    if (FG_SPEC_FOVEATED == 0) return false;
    return fg_frame.fovea_radius > 0.0 && view != FG_VIEW_CENTRE;
}

// The fovea's centre in pixels: where the lens's optical axis meets the image.
vec2 fg_fovea_centre(int view)
{
    GpuView v = fg_frame.views[view];
    return (v.lens_radii.x > 0.0 ? v.lens_centre : vec2(0.5)) * vec2(fg_view_size(view));
}

// Fixed foveation: 0 inside the fovea (around the lens centre), rising to 1 across the blend band,
// 1 in the periphery.
float fg_periphery(int view, ivec2 pixel)
{
    if (!fg_foveated(view)) return 0.0;
    vec2 size = vec2(fg_view_size(view));
    float r = length(vec2(pixel) + 0.5 - fg_fovea_centre(view)) / (0.5 * size.y);
    return clamp((r - fg_frame.fovea_radius) / max(fg_frame.fovea_blend, 1e-6), 0.0, 1.0);
}

// Foveation splits each per-eye pass into two dispatches, so that no SIMD lane idles on a skipped
// pixel: the full-resolution one (stride 1) takes the pixels short of the periphery, the
// periphery's own (stride 2, a quarter of the invocations) the even pixel of each 2x2 block beyond,
// inside the lens or not (a pixel outside it only gets its miss; the fovea pass writes the odd ones).
bool fg_dispatch_takes(int view, ivec2 pixel, int stride)
{
    return (fg_periphery(view, pixel) >= 1.0) == (stride == 2);
}

// tan of the half-angle of one output pixel: the hit rule (d < epsilon * this * t) and the normal
// taps. The same in the fovea and the periphery, and at any march resolution.
float fg_detail_tan()
{
    return tan(min(fg_frame.detail_cone, 1.5));
}

// The final image holds display-encoded (sRGB) values: a pass that filters or blends them decodes
// to linear light first (mixing encoded values darkens every edge between light and dark).
vec3 fg_srgb_to_linear(vec3 c)
{
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

vec3 fg_linear_to_srgb(vec3 c)
{
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

// Area lights (the implicit input `light_sample`, light.soft_shadow): this sample's point of the unit
// square (xy, which the node maps onto the light's disc) and 1 while offline samples accumulate (z),
// or all 0 in a single frame.
// Sample k of a pixel is point k of the Sobol (0,2)-sequence, Owen-scrambled by a seed of the
// pixel's own (Burley's hash-based scrambling): every prefix of a pixel's points covers the disc
// evenly, each power-of-two prefix stratified in every elementary interval, so a penumbra's error
// falls faster than with one shifted low-discrepancy sequence (the lit bulb at 16 samples: see
// docs/shading.md), and neighbouring pixels' errors do not repeat each other. The shade and AOV
// passes set the pixel.
ivec2 fg_shading_pixel = ivec2(0);

// Point k of the first two Sobol dimensions (van der Corput, and the dimension of x + 1), as
// 32-bit binary fractions.
uvec2 fg_sobol2(uint k)
{
    uvec2 p = uvec2(0u);
    uint v = 0x80000000u;
    for (uint bit = 0u; k != 0u; ++bit, k >>= 1u) {
        if ((k & 1u) != 0u) p ^= uvec2(0x80000000u >> bit, v);
        v ^= v >> 1u;
    }
    return p;
}

// Owen's nested uniform scrambling of a 32-bit fraction, by the hash of Burley (JCGT 2020) after
// Laine and Karras: each digit flips by a function of the seed and the digits above it.
uint fg_owen_scramble(uint x, uint seed)
{
    x = bitfieldReverse(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return bitfieldReverse(x);
}

// This sample's point of the unit square for one stochastic term (`stream`: 0 the area lights, 1
// the environment on surfaces, 2 the fog's point along the ray (x) and a medium's offset along it
// (y, volume.glsl), 3 the fog's direction of the sky, 4 to 9 a glass ray's choices at each exit,
// 10 the environment in the specular lobe), scrambled by a seed of the pixel's and the term's own, so that the terms' points do not line up
// with each other.
vec2 fg_sample_square(uint stream)
{
    // A small integer hash of the pixel (PCG-style, two rounds): the two dimensions' seeds.
    uvec2 h = uvec2(fg_shading_pixel) * 1664525u + 1013904223u;
    h.x += h.y * 1664525u;
    h.y += h.x * 1664525u;
    h ^= h >> 16u;
    h.x += h.y * 1664525u;
    h.y += h.x * 1664525u;
    h ^= h >> 16u;
    h ^= stream * uvec2(0x9e3779b9u, 0x7f4a7c15u);
    uvec2 p = fg_sobol2(uint(fg_frame.area_light.x));
    uvec2 scrambled = uvec2(fg_owen_scramble(p.x, h.x), fg_owen_scramble(p.y, h.y));
    // The top 24 bits: a float's, so that no point rounds up to 1.
    return vec2(scrambled >> 8u) * (1.0 / 16777216.0);
}

vec3 fg_light_sample()
{
    if (fg_frame.area_light.z == 0.0) return vec3(0.0);
    return vec3(fg_sample_square(0u), 1.0);
}
