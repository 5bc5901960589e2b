// Shared by every pass: the frame and scene uniforms, ray generation and the march helpers.
// The compiler pastes this after the knob constants and before the scene's code.

// One view: an eye (left, right) or the centre eye used by stereo reprojection.
struct FgView {
    vec4 origin;    // xyz eye position in scene units
    vec4 right;     // xyz unit right axis
    vec4 up;        // xyz unit up axis
    vec4 forward;   // xyz unit forward axis
    vec4 tan_fov;   // tangents of the frustum edges: x left (<0), y right, z down (<0), w up
};

layout(set = 0, binding = 0, std140) uniform FgFrame {
    FgView views[3];     // 0 left, 1 right, 2 centre
    uvec4 size;          // x, y full-resolution size; z frame index; w unused
    vec4 time;           // x seconds, y world scale, z interpupillary distance (scene units), w unused
    vec4 pixel;          // x tangent of the half-diagonal of one full-resolution pixel, y, z, w unused
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
    vec4 misc2;          // x foveation blend, yzw unused
} fg_scene;

// Ray direction through a point of a view's image plane, uv in [0, 1]^2 with y down.
vec3 fg_ray_dir(int view, vec2 uv)
{
    FgView v = fg_frame.views[view];
    float tx = mix(v.tan_fov.x, v.tan_fov.y, uv.x);
    float ty = mix(v.tan_fov.w, v.tan_fov.z, uv.y);
    return normalize(v.forward.xyz + tx * v.right.xyz + ty * v.up.xyz);
}

vec3 fg_ray_origin(int view)
{
    return fg_frame.views[view].origin.xyz;
}

// The interval [near, far] of a ray inside the scene bounds, grown by `margin` (cone radius per
// unit distance) so a cone around the ray is inside whenever any of its rays is. Empty: near > far.
vec2 fg_bounds_interval(vec3 ro, vec3 rd, float margin)
{
    vec3 oc = ro - fg_scene.bounds.xyz;
    float b = dot(oc, rd);
    float c = dot(oc, oc);
    float radius = fg_scene.bounds.w;
    // The grown sphere radius at distance t is radius + margin * t; use the far limit's growth.
    float grown = radius + margin * fg_scene.misc.y;
    float h = b * b - (c - grown * grown);
    if (h < 0.0) return vec2(1.0, 0.0);
    h = sqrt(h);
    return vec2(max(-b - h, 0.0), min(-b + h, fg_scene.misc.y));
}

// Radius of a pixel's cone at distance t, for a pixel 2^level full-resolution pixels wide.
float fg_cone_tan(int level)
{
    // tan of the cone's half-angle; the tangent-plane half-diagonal bounds the angle from above.
    return tan(min(fg_frame.pixel.x * float(1 << level), 1.5));
}

// Counting distance evaluations: a buffer of per-pass totals, compiled out unless the knob is on.
#define FG_MISS (-1.0)
