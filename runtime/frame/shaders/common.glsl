// Shared by every pass: the frame and scene uniforms, ray generation and the march helpers.
// The compiler pastes this after the knob constants and before the scene's code.

// One view: an eye (left, right) or the centre eye used by stereo reprojection.
struct FgView {
    vec4 origin;    // xyz eye position in scene units
    vec4 right;     // xyz unit right axis
    vec4 up;        // xyz unit up axis
    vec4 forward;   // xyz unit forward axis
    vec4 tan_fov;   // tangents of the frustum edges: x left (<0), y right, z down (<0), w up
    vec4 lens;      // the lens mask: an ellipse in uv, xy centre, zw radii; zw = 0 when off
};

layout(set = 0, binding = 0, std140) uniform FgFrame {
    FgView views[3];     // 0 left, 1 right, 2 centre
    uvec4 size;          // xy eye image size, zw centre-eye image size (wider: it covers both eyes)
    uvec4 info;          // x frame index, y cone levels, z projection (FG_PROJECTION_*), w unused
    vec4 time;           // x seconds, y world scale, z interpupillary distance (scene units), w unused
    vec4 pixel;          // x tangent of the half-diagonal of one full-resolution pixel; y tangent per pixel
    vec4 foveation;      // x fovea radius in half image heights (0: off), y blend band width
    // The camera (centre eye) in double, as hi + lo floats. Packs of precision "double" evaluate
    // the scene at fg_anchor() + p, and every origin above is then relative to it.
    vec4 anchor_hi;
    vec4 anchor_lo;
} fg_frame;

layout(set = 0, binding = 1, std140) uniform FgScene {
    vec4 light_dir;      // xyz unit direction towards the light
    vec4 light_color;
    vec4 ambient;
    vec4 sss_color;
    vec4 rim_color;
    vec4 albedo;         // used when the graph binds no albedo
    vec4 bg_top;
    vec4 bg_bottom;
    vec4 fog;            // rgb colour, a density per scene unit
    vec4 glow;           // rgb colour * intensity, a falloff distance
    vec4 bounds;         // xyz centre, w radius: rays outside this sphere miss
    vec4 misc;           // x exposure, y far limit, z vignette strength, w foveation inner radius
    vec4 misc2;          // x foveation blend, y fade to black (0 none, 1 black), zw unused
    vec4 bounds_lo;      // xyz: the bounds' centre less its float value (precision "double" adds it)
} fg_scene;

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
    return vec3((dvec3(fg_scene.bounds.xyz) + dvec3(fg_scene.bounds_lo.xyz)) - fg_anchor());
#else
    return fg_scene.bounds.xyz;
#endif
}

// How a pixel becomes a ray (fg_frame.info.z, the same for every pass of a frame): the view's
// perspective frustum (the headset), or offline panoramas: equirectangular around the view's
// origin, and omni-directional stereo (ODS), where each column's eye sits on the circle of the
// interpupillary distance, looking along the tangent, as 360-degree stereo video players expect.
#define FG_PROJECTION_PERSPECTIVE 0u
#define FG_PROJECTION_EQUIRECT 1u
#define FG_PROJECTION_ODS 2u

// Longitude (0 straight ahead, positive to the right) and latitude (positive up) of a panorama's
// uv in [0, 1]^2, y down.
vec2 fg_panorama_angles(vec2 uv)
{
    return vec2((uv.x - 0.5) * 6.28318531, (0.5 - uv.y) * 3.14159265);
}

// Ray direction through a point of a view's image, uv in [0, 1]^2 with y down.
vec3 fg_ray_dir(int view, vec2 uv)
{
    FgView v = fg_frame.views[view];
    if (fg_frame.info.z != FG_PROJECTION_PERSPECTIVE) {
        vec2 a = fg_panorama_angles(uv);
        return cos(a.y) * (sin(a.x) * v.right.xyz + cos(a.x) * v.forward.xyz) + sin(a.y) * v.up.xyz;
    }
    float tx = mix(v.tan_fov.x, v.tan_fov.y, uv.x);
    float ty = mix(v.tan_fov.w, v.tan_fov.z, uv.y);
    return normalize(v.forward.xyz + tx * v.right.xyz + ty * v.up.xyz);
}

// Ray origin of a pixel: the view's eye, except in ODS, where the left (view 0) and right eye
// (view 1) of each column sit half the IPD to either side of the head, across that column's
// direction (the views' origins are the head's centre then).
vec3 fg_ray_origin(int view, vec2 uv)
{
    FgView v = fg_frame.views[view];
    if (fg_frame.info.z == FG_PROJECTION_ODS && view != 2) {
        float lon = fg_panorama_angles(uv).x;
        float side = view == 0 ? -0.5 : 0.5;
        return v.origin.xyz + side * fg_frame.time.z * (cos(lon) * v.right.xyz - sin(lon) * v.forward.xyz);
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
    float radius = fg_scene.bounds.w + spread;
    float far = fg_scene.misc.y;
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
    return tan(min(fg_frame.pixel.x * float(1 << level), 1.5));
}

ivec2 fg_view_size(int view)
{
    return ivec2(view == 2 ? fg_frame.size.zw : fg_frame.size.xy);
}

// How far the eyes of a conemarch block 2^level columns wide sit from the eye of its centre
// column: 0 but in ODS, where the eye moves along the IPD circle by at most the arc of half the
// block's longitude. A cone whose radius grows by this much covers the rays of every eye.
float fg_origin_spread(int view, int level)
{
    if (fg_frame.info.z != FG_PROJECTION_ODS || view == 2) return 0.0;
    return 0.5 * fg_frame.time.z * 3.14159265 * float(1 << level) / float(fg_view_size(view).x);
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

// A miss in a depth image. Depths are distances along the ray, never NaN or infinite.
#define FG_MISS (-1.0)

// The lens mask (seed 001's "iris"): a pixel whose footprint lies wholly outside the ellipse the
// headset's lens shows is never marched or shaded. `margin` (uv) widens the ellipse by a coarse
// footprint, so a coarse level skips a block only if every child pixel skips too.
bool fg_outside_lens(int view, vec2 uv, vec2 margin)
{
    vec4 lens = fg_frame.views[view].lens;
    if (lens.z <= 0.0) return false;
    vec2 q = (uv - lens.xy) / (lens.zw + margin);
    return dot(q, q) > 1.0;
}

bool fg_outside_lens(int view, ivec2 pixel)
{
    return fg_outside_lens(view, (vec2(pixel) + 0.5) / vec2(fg_view_size(view)), vec2(0.0));
}

// Fixed foveation: 0 inside the fovea (around the lens centre), rising to 1 across the blend band,
// 1 in the periphery. The centre eye of stereo reprojection is never foveated.
float fg_periphery(int view, ivec2 pixel)
{
    if (fg_frame.foveation.x <= 0.0 || view == 2) return 0.0;
    vec2 size = vec2(fg_view_size(view));
    vec4 lens = fg_frame.views[view].lens;
    vec2 centre = (lens.z > 0.0 ? lens.xy : vec2(0.5)) * size;
    float r = length(vec2(pixel) + 0.5 - centre) / (0.5 * size.y);
    return clamp((r - fg_frame.foveation.x) / max(fg_frame.foveation.y, 1e-6), 0.0, 1.0);
}

// Foveation splits each per-eye pass into two dispatches, so that no SIMD lane idles on a skipped
// pixel: the full-resolution one (stride 1) takes the pixels short of the periphery, the
// periphery's own (stride 2, a quarter of the invocations) the even pixel of each 2x2 block beyond.
bool fg_dispatch_takes(int view, ivec2 pixel, int stride)
{
    // Pixels outside the lens cost nothing (they only write a miss): the first dispatch takes them.
    bool periphery = fg_periphery(view, pixel) >= 1.0 && !fg_outside_lens(view, pixel);
    return periphery == (stride == 2);
}

// The hit threshold's footprint in full-resolution pixels: 2 where a pixel stands for its block.
float fg_footprint(int view, ivec2 pixel)
{
    return fg_periphery(view, pixel) >= 1.0 ? 2.0 : 1.0;
}
