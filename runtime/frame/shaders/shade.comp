//! pass: shade
//! needs: surface
//! when: always
//! include: post_effects.glsl
//! include: dispatch_tiles.glsl
//! include-after-scene: environment.glsl
//! include-after-scene: shading.glsl
//! include-after-scene: kept_shading.glsl
//! include-after-scene: volume.glsl
// Shades each hit of one eye: the graph's surface outputs (albedo, fake lighting, emission), a
// finite-difference normal only if something needs it, and the background for misses; then the
// post effects the pack lists (a medium drawn as nodes, fog, glow, vignette: each a function of
// this pixel alone, so they cost no pass of their own) and the tone map, into the final image.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_depth;
layout(set = 0, binding = 4, rgba8) uniform writeonly image2D fg_final;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 11, r32f) uniform readonly image2D fg_glow;   // closest approach, from the march
#endif
// Shading reuse across the eyes (FG_SHADE_REUSE): this eye's shading before post effects and the
// tone map (fg_pack_kept), and the other eye's with its depth (bound either way; written only with
// reuse).
layout(set = 0, binding = 12, rgba32ui) uniform writeonly uimage2D fg_shaded;
layout(set = 0, binding = 5, rgba32ui) uniform readonly uimage2D fg_other_color;
layout(set = 0, binding = 6, r32f) uniform readonly image2D fg_other_depth;
// This eye's shading of the frame before and of this one, for FG_SHADE_HISTORY (bound either way).
layout(set = 0, binding = 7, rgba32ui) uniform readonly uimage2D fg_history_color;
layout(set = 0, binding = 8, r32f) uniform readonly image2D fg_history_depth;
layout(set = 0, binding = 9, rgba32ui) uniform writeonly uimage2D fg_cache_color;
layout(set = 0, binding = 10, r32f) uniform writeonly image2D fg_cache_depth;
// The tone map's input and the fade's share kept, for samples averaged before the tone map (pc.hdr).
layout(set = 0, binding = 13, rgba32f) uniform writeonly image2D fg_hdr;
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

// The hit of view o's pixel `at` at distance t, on its ray through the pixel's centre.
vec3 fg_hit_of_pixel(GpuView o, ivec2 at, float t)
{
    vec2 c = (vec2(at) + 0.5) / vec2(fg_frame.eye_size);
    vec3 dir = normalize(o.forward.xyz + mix(o.tan_fov.x, o.tan_fov.y, c.x) * o.right.xyz +
                         mix(o.tan_fov.w, o.tan_fov.z, c.y) * o.up.xyz);
    return o.origin.xyz + dir * t;
}

// Shading reuse across the eyes: the point p, seen by the other eye, lands on one of its pixels;
// where that pixel's hit (on its ray through the pixel's centre) lies within FG_SHADE_REUSE cone
// radii of p, its shading is taken instead of shading p again (the caller recomputes the terms that
// read the view).
bool fg_reuse_other_eye(vec3 p, out FgKeptShading kept)
{
    if (fg_projection() != FG_PROJECTION_PERSPECTIVE) return false;
    int other = 1 - pc.view;
    GpuView o = fg_frame.views[other];
    ivec2 at;
    if (!fg_shaded_pixel_of(other, o, p, at) || fg_outside_lens(other, at)) return false;
    float t_other = imageLoad(fg_other_depth, at).x;
    if (t_other < 0.0) return false;
    float seen = length(p - o.origin.xyz);
    if (length(fg_hit_of_pixel(o, at, t_other) - p) > FG_SHADE_REUSE * fg_cone_tan(0) * seen) return false;
    kept = fg_unpack_kept(imageLoad(fg_other_color, at));
    return true;
}

// Shading history: the point p, seen by this eye in the frame before, lands on one of its pixels;
// where that pixel's hit is the same point (within FG_SHADE_HISTORY cone radii), its shading is
// taken. Packs with rim or SSS never take one (the frame graph checks). A shading is recomputed
// after kHistoryAge takes, so the drift of one taken again and again stays within kHistoryAge + 1
// frames' tolerances.
const float kHistoryAge = 2.0;

bool fg_reuse_previous_frame(vec3 p, float t, out FgKeptShading kept)
{
    GpuView o = fg_frame.previous[pc.view];
    ivec2 at;
    if (!fg_shaded_pixel_of(pc.view, o, p, at)) return false;
    float t_old = imageLoad(fg_history_depth, at).x;
    if (t_old < 0.0) return false;
    kept = fg_unpack_kept(imageLoad(fg_history_color, at));
    if (kept.age >= kHistoryAge) return false;
    return length(fg_hit_of_pixel(o, at, t_old) - p) <= FG_SHADE_HISTORY * fg_cone_tan(0) * t;
}

// The final pixel: the post effects the pack lists, the tone map, and the fade (snap turns, the
// head in the surface), which scales the displayed image linearly.
void fg_store_final(ivec2 pixel, vec3 color, vec3 ro, vec3 rd, float t)
{
    float closest = 0.0;
#ifdef FG_HAS_GLOW
    closest = imageLoad(fg_glow, pixel).x;
#endif
#ifdef FG_HAS_VOLUME
    color = fg_through_volume(color, ro, rd, t);
#endif
    vec3 scattered = vec3(0.0);
#ifdef FG_HAS_FOG
    scattered = fg_fog_light(ro, rd, t);
#endif
    color = fg_post_effects(color, pixel, ivec2(fg_frame.eye_size), ro, rd, t, closest, scattered);
    imageStore(fg_final, pixel, vec4(fg_tonemap(color) * (1.0 - fg_scene.fade), 1.0));
    if (pc.hdr != 0) imageStore(fg_hdr, pixel, vec4(color * fg_scene.exposure, 1.0 - fg_scene.fade));
}

void main()
{
    ivec2 pixel = fg_dispatch_cell(pc.stride, ivec2(gl_GlobalInvocationID.xy));
    ivec2 size = ivec2(fg_frame.eye_size);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    fg_shading_pixel = pixel;
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
    FgKeptShading kept = FgKeptShading(vec3(0.0), vec3(0.0), 0.0);
    if (t < 0.0) {
        color = fg_background(rd);
    } else {
        vec3 p = ro + rd * t;
        bool taken = false;
        if (kShadingTravels && FG_SHADE_REUSE > 0.0 && pc.reuse != 0) taken = fg_reuse_other_eye(p, kept);
        if (kShadingTravels && !taken && FG_SHADE_HISTORY > 0.0 && fg_frame.shade_history != 0u)
            taken = fg_reuse_previous_frame(p, t, kept);
        vec3 n = vec3(0.0, 1.0, 0.0);
#ifdef FG_HAS_NORMALS
        if (!taken || kHasViewTerms) n = fg_surface_normal(p, t);
#endif
        if (taken) {
            color = fg_kept_color(kept, p, rd, n);
            kept.age += 1.0;
        } else {
            FgShading shading = fg_shade_hit(p, rd, n, t);
            color = shading.color;
            if (FG_SHADE_REUSE > 0.0 || FG_SHADE_HISTORY > 0.0) kept = fg_keep_shading(shading);
        }
    }
    if (FG_SHADE_REUSE > 0.0) imageStore(fg_shaded, pixel, fg_pack_kept(kept));
    if (FG_SHADE_HISTORY > 0.0) {
        imageStore(fg_cache_color, pixel, fg_pack_kept(kept));
        imageStore(fg_cache_depth, pixel, vec4(t));
    }
    fg_store_final(pixel, color, ro, rd, t);
}
