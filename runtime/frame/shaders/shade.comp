//! pass: shade
//! needs: surface
//! when: always
//! include: post_effects.glsl
//! include: dispatch_tiles.glsl
//! include-after-scene: shading.glsl
// Shades each hit of one eye: the graph's surface outputs (albedo, fake lighting, emission), a
// finite-difference normal only if something needs it, and the background for misses; then the
// post effects the pack lists (fog, glow, vignette: each a function of this pixel alone, so they
// cost no pass of their own) and the tone map, into the final image.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_depth;
layout(set = 0, binding = 4, rgba8) uniform writeonly image2D fg_final;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 11, r32f) uniform readonly image2D fg_glow;   // closest approach, from the march
#endif
// Shading reuse across the eyes (FG_SHADE_REUSE): this eye's colour before post effects and the
// tone map, and the other eye's with its depth (bound either way; written only with reuse).
layout(set = 0, binding = 12, rgba16f) uniform writeonly image2D fg_shaded;
layout(set = 0, binding = 5, rgba16f) uniform readonly image2D fg_other_color;
layout(set = 0, binding = 6, r32f) uniform readonly image2D fg_other_depth;
// This eye's shading of the frame before and of this one, for FG_SHADE_HISTORY (bound either way).
layout(set = 0, binding = 7, rgba16f) uniform readonly image2D fg_history_color;   // rgb, a = age
layout(set = 0, binding = 8, r32f) uniform readonly image2D fg_history_depth;
layout(set = 0, binding = 9, rgba16f) uniform writeonly image2D fg_cache_color;
layout(set = 0, binding = 10, r32f) uniform writeonly image2D fg_cache_depth;
layout(push_constant) uniform FgShadePush { ShadePush pc; };

// The pixel of view o (an eye `eye` shaded, this frame or the one before) that the point p lands
// on; false when p is behind it, outside its image, or on a pixel foveation left unshaded (the
// fovea pass filled it).
bool fg_shaded_pixel_of(int eye, GpuView o, vec3 p, out ivec2 at)
{
    vec3 q = p - o.origin.xyz;
    float z = dot(q, o.forward.xyz);
    if (z <= 0.0) return false;
    vec2 tangent = vec2(dot(q, o.right.xyz), dot(q, o.up.xyz)) / z;
    vec2 uv = vec2((tangent.x - o.tan_fov.x) / (o.tan_fov.y - o.tan_fov.x),
                   (o.tan_fov.w - tangent.y) / (o.tan_fov.w - o.tan_fov.z));
    ivec2 size = ivec2(fg_frame.eye_size);
    at = ivec2(floor(uv * vec2(size)));
    if (any(lessThan(at, ivec2(0))) || any(greaterThanEqual(at, size))) return false;
    return ((at.x | at.y) & 1) == 0 || fg_periphery(eye, at) < 1.0;
}

// Shading reuse across the eyes: the point p, seen by the other eye, lands on one of its pixels;
// where that pixel's hit is the same point (depth agrees within FG_SHADE_REUSE cone radii), its
// colour is taken instead of shading p again. View-dependent terms (rim, SSS) then come from the
// other eye's direction: the benchmark measures what that costs.
bool fg_reuse_other_eye(vec3 p, out vec4 color)
{
    if (fg_projection() != FG_PROJECTION_PERSPECTIVE) return false;
    int other = 1 - pc.view;
    GpuView o = fg_frame.views[other];
    ivec2 at;
    if (!fg_shaded_pixel_of(other, o, p, at) || fg_outside_lens(other, at)) return false;
    float t_other = imageLoad(fg_other_depth, at).x;
    float seen = length(p - o.origin.xyz);
    if (t_other < 0.0 || abs(t_other - seen) > FG_SHADE_REUSE * fg_cone_tan(0) * seen) return false;
    color = imageLoad(fg_other_color, at);
    return true;
}

// Shading history: the point p, seen by this eye in the frame before, lands on one of its pixels;
// where that pixel's hit is the same point (within FG_SHADE_HISTORY cone radii), its colour is
// taken. Only view-independent shading qualifies (no rim, no SSS: the frame graph checks), and a
// colour is recomputed after kHistoryAge reuses so small errors cannot accumulate.
const float kHistoryAge = 2.0;

bool fg_reuse_previous_frame(vec3 p, float t, out vec4 color)
{
    GpuView o = fg_frame.previous[pc.view];
    ivec2 at;
    if (!fg_shaded_pixel_of(pc.view, o, p, at)) return false;
    float t_old = imageLoad(fg_history_depth, at).x;
    if (t_old < 0.0) return false;
    color = imageLoad(fg_history_color, at);
    if (color.a >= kHistoryAge) return false;
    // The old pixel's hit, on the old ray through its centre.
    vec2 c = (vec2(at) + 0.5) / vec2(fg_frame.eye_size);
    vec3 old_dir = normalize(o.forward.xyz + mix(o.tan_fov.x, o.tan_fov.y, c.x) * o.right.xyz +
                             mix(o.tan_fov.w, o.tan_fov.z, c.y) * o.up.xyz);
    vec3 old_hit = o.origin.xyz + old_dir * t_old;
    return length(old_hit - p) <= FG_SHADE_HISTORY * fg_cone_tan(0) * t;
}

// The final pixel: the post effects the pack lists, the tone map, and the fade (snap turns, the
// head in the surface), which scales the displayed image linearly.
void fg_store_final(ivec2 pixel, vec3 color, float t)
{
    float closest = 0.0;
#ifdef FG_HAS_GLOW
    closest = imageLoad(fg_glow, pixel).x;
#endif
    color = fg_post_effects(color, pixel, ivec2(fg_frame.eye_size), t, closest);
    imageStore(fg_final, pixel, vec4(fg_tonemap(color) * (1.0 - fg_scene.fade), 1.0));
}

void main()
{
    ivec2 pixel = fg_dispatch_cell(pc.stride, ivec2(gl_GlobalInvocationID.xy));
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, pixel)) {
        imageStore(fg_final, pixel, vec4(0.0, 0.0, 0.0, 1.0));
        if (FG_SHADE_HISTORY > 0.0) imageStore(fg_cache_depth, pixel, vec4(-1.0));
        return;
    }
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 ro = fg_ray_origin(pc.view, uv);
    vec3 rd = fg_ray_dir(pc.view, uv);
    float t = imageLoad(fg_depth, pixel).x;
    vec3 color;
    float age = 0.0;
    bool from_other_eye = false;
    if (t < 0.0) {
        color = fg_background(rd);
    } else {
        vec3 p = ro + rd * t;
        vec4 reused;
        if (FG_SHADE_REUSE > 0.0 && pc.reuse != 0 && fg_reuse_other_eye(p, reused)) {
            color = reused.rgb;
            from_other_eye = true;
        } else if (FG_SHADE_HISTORY > 0.0 && fg_frame.shade_history != 0u && fg_reuse_previous_frame(p, t, reused)) {
            color = reused.rgb;
            age = reused.a + 1.0;
        } else {
            vec3 n = vec3(0.0, 1.0, 0.0);
#ifdef FG_HAS_NORMALS
            n = fg_surface_normal(p, t);
#endif
            color = fg_shade_hit(p, rd, n).color;
        }
    }
    if (FG_SHADE_REUSE > 0.0) imageStore(fg_shaded, pixel, vec4(color, 1.0));
    if (FG_SHADE_HISTORY > 0.0) {
        // The other eye's colour saw the point from there: no source for the next frame.
        imageStore(fg_cache_color, pixel, vec4(color, age));
        imageStore(fg_cache_depth, pixel, vec4(from_other_eye ? -1.0 : t));
    }
    fg_store_final(pixel, color, t);
}
