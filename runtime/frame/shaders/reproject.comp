//! pass: reproject
//! needs: distance
//! when: always
//! include: march_counters.glsl
//! include: dispatch_tiles.glsl
// Stereo reprojection (after van de Hoef and Zalmstra's gather, as Framestore used it): each eye's
// ray walks the centre eye's conemarch levels instead of the scene. A point of the eye ray is
// empty space if it is closer to the centre eye than the centre's lower bound for the pixel it
// projects into (each pixel's cone is empty up to that distance, and a cone cut by a ball is
// convex, so whole segments are proven empty cell by cell). Coarse levels skip far, fine levels
// get close; where the centre eye could not see (disocclusion, outside its image) or the bound
// stops short, the eye sphere-traces on its own from the bound (the fix-up march).

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, rg32f) uniform readonly image2D fg_centre_levels;
layout(set = 0, binding = 5, r32f) uniform writeonly image2D fg_depth;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 6, r32f) uniform readonly image2D fg_centre_glow;
layout(set = 0, binding = 7, r32f) uniform writeonly image2D fg_glow;
#endif
layout(push_constant) uniform FgReprojectPush { ReprojectPush pc; };

const float FG_HUGE = 1e30;

// The centre eye's camera, and the eye ray relative to it: a point of the eye ray is
// o_c + b + r t, with b = o_e - o_c.
GpuView C;
vec3 b;
vec3 r;
ivec2 centre_size;

// Tangent-plane coordinates of b + r t seen from the centre eye; w > 0 when in front of it.
vec3 centre_tan(float t)
{
    vec3 q = b + r * t;
    float f = dot(q, C.forward.xyz);
    return vec3(dot(q, C.right.xyz) / f, dot(q, C.up.xyz) / f, f);
}

// Full-resolution centre pixel coordinates of tangent coordinates (y down).
vec2 centre_pixel(vec2 tan)
{
    return (tan - vec2(C.tan_fov.x, C.tan_fov.w)) / vec2(C.tan_fov.y - C.tan_fov.x, C.tan_fov.z - C.tan_fov.w) *
           vec2(centre_size);
}

// Distance t where the ray's projection crosses tangent value X of the axis `axis` (right or up).
float crossing(vec3 axis, float X, float after)
{
    float den = dot(r, axis) - X * dot(r, C.forward.xyz);
    if (abs(den) < 1e-20) return FG_HUGE;
    float t = (X * dot(b, C.forward.xyz) - dot(b, axis)) / den;
    return t > after ? t : FG_HUGE;
}

// Where the ray leaves the ball of radius D around the centre eye (the larger root).
float ball_exit(float D)
{
    float bb = dot(b, r);
    float h = bb * bb - (dot(b, b) - D * D);
    return h < 0.0 ? -FG_HUGE : -bb + sqrt(h);
}

// Advance t through cells of one centre level while every point passed is provably empty.
// Returns the new lower bound; `evaluations` is untouched (no scene evaluation here).
float walk_level(int level, float t, float t_max)
{
    ivec4 rect = fg_level_rect(level, centre_size);
    float cell = float(1 << level);
    vec2 tan_per_pixel = vec2(C.tan_fov.y - C.tan_fov.x, C.tan_fov.z - C.tan_fov.w) / vec2(centre_size);
    for (int i = 0; i < FG_REPROJECT_STEPS && t < t_max; ++i) {
        vec3 ct = centre_tan(t);
        if (ct.z <= 0.0) return t;                       // behind the centre eye: no data
        vec2 px = centre_pixel(ct.xy);
        if (any(lessThan(px, vec2(0.0))) || any(greaterThanEqual(px, vec2(centre_size)))) return t;
        ivec2 c = ivec2(px / cell);
        vec2 bound_sample = imageLoad(fg_centre_levels, rect.xy + c).xy;
        // Level 0's hit depth is exact only along the pixel's centre ray: trusting it (the seeds'
        // choice) gets closer but can misplace sub-pixel detail; the cone bound never does.
        float D = (level == 0 && FG_REPROJECT_TRUST_DEPTH && bound_sample.x >= 0.0) ? bound_sample.x : bound_sample.y;
        vec3 q = b + r * t;
        if (dot(q, q) >= D * D) return t;                // a surface may be here, seen from the centre
        // Leave the cell through one of its four edges, or the empty ball, whichever comes first.
        vec2 lo = vec2(C.tan_fov.x, C.tan_fov.w) + vec2(c) * cell * tan_per_pixel;
        vec2 hi = lo + cell * tan_per_pixel;
        float exit_t = min(min(crossing(C.right.xyz, lo.x, t), crossing(C.right.xyz, hi.x, t)),
                           min(crossing(C.up.xyz, lo.y, t), crossing(C.up.xyz, hi.y, t)));
        float ball = ball_exit(D);
        if (ball <= exit_t) return max(t, ball * (1.0 - 1e-6));
        t = exit_t * (1.0 + 1e-6) + 1e-9;
    }
    return min(t, t_max);
}

void main()
{
    ivec2 pixel = fg_dispatch_cell(pc.stride, fg_invocation_cell());
    ivec2 size = fg_view_size(pc.view);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, pixel)) {
        imageStore(fg_depth, pixel, vec4(FG_MISS));
#ifdef FG_HAS_GLOW
        imageStore(fg_glow, pixel, vec4(FG_HUGE));
#endif
        return;
    }
    C = fg_frame.views[FG_VIEW_CENTRE];
    centre_size = fg_view_size(FG_VIEW_CENTRE);
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 ro = fg_ray_origin(pc.view, uv);
    r = fg_ray_dir(pc.view, uv);
    b = ro - C.origin.xyz;
    vec2 range = fg_bounds_interval(ro, r, 0.0);
    float cone = fg_detail_tan();
    float result = FG_MISS;
    float closest = FG_HUGE;
    uint evaluations = 0u;
    if (range.x <= range.y) {
        float t = range.x;
        int budget = FG_MAX_STEPS;
        bool hit = false;
        bool done = false;
        while (!done) {
            // Skip what the centre eye proves empty, coarse levels first.
            float before = t;
            for (int level = pc.levels - 1; level >= 0; --level) t = walk_level(level, t, range.y);
            if (t >= range.y) break;
            // Fix-up: sphere-trace from the bound. Where the centre eye has no data (the point is
            // beside or level with it) take one step and look again; else march on for a while.
            int steps = t > before ? FG_FIXUP_STEPS : 1;
            for (int i = 0; i < steps && budget > 0; ++i, --budget) {
                fg_count_iteration(true);
                float d = fg_scene_distance(ro + r * t) * FG_STEP_SCALE;
                evaluations++;
                closest = min(closest, d);
                if (d < FG_EPSILON * FG_STEP_FRACTION * cone * t) {
                    hit = true;
                    done = true;
                    break;
                }
                t += d;
                if (t > range.y) {
                    done = true;
                    break;
                }
            }
            if (budget <= 0) {
                done = true;
                hit = !FG_MISS_ON_STEP_CAP && t <= range.y;
            }
        }
        if (hit) result = t;
    }
    imageStore(fg_depth, pixel, vec4(result));
#ifdef FG_HAS_GLOW
    // Glow is low-frequency: take the centre eye's at the ray's own direction, and the fix-up's.
    vec3 far_tan = vec3(dot(r, C.right.xyz), dot(r, C.up.xyz), dot(r, C.forward.xyz));
    vec2 px = clamp(centre_pixel(far_tan.xy / max(far_tan.z, 1e-6)), vec2(0.0), vec2(centre_size - 1));
    closest = min(closest, imageLoad(fg_centre_glow, ivec2(px)).x);
    imageStore(fg_glow, pixel, vec4(closest));
#endif
    fg_count_flush(pc.counter_slot, evaluations);
}
