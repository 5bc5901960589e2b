//! pass: conemarch
//! needs: distance
//! when: always
//! include: tail_queue.glsl
// Progressive cone marching (Fulcrum's Fractus, Framestore's VR fractals), one dispatch per level
// from coarse to fine. A level-k pixel marches a cone that covers its 2^k x 2^k footprint, starting
// where its parent stopped, and stops as soon as the cone may touch a surface: its distance is a
// lower bound for every ray in its footprint, so the next level can start there. Level 0 marches
// the pixel's own ray to the hit, and also records where the pixel's cone first touched (a lower
// bound for the whole pixel), which stereo reprojection uses.
//
// The levels of a view live in one atlas image (see fg_level_rect): x = depth (level 0: the hit or
// FG_MISS; coarser: the cone's lower bound), y = the cone's lower bound.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, rg32f) uniform image2D fg_levels;
layout(set = 0, binding = 4, std430) buffer FgCounters { uint evaluations[]; } fg_counters;
layout(set = 0, binding = 5, r32f) uniform writeonly image2D fg_depth;     // level 0: the eye's depth image
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 6, r32f) uniform writeonly image2D fg_glow;      // level 0: closest approach
#endif
layout(push_constant) uniform FgConePush {
    int view;
    int level;           // 0 = full resolution
    int top;             // 1 for the coarsest level: no parent
    int counter_slot;
    int stride;          // level 0: 1, or 2 for the foveated periphery's dispatch
} pc;

// Full resolution with FG_TAIL_AFTER > 0: a pixel still marching after that many steps goes to
// the tail queue (tail.comp finishes it).
bool fg_defer(int step) { return FG_TAIL_AFTER > 0 && step == FG_TAIL_AFTER; }

// A bound beyond every ray's exit: children of an escaped cone miss at once.
float fg_escaped() { return fg_scene.misc.y * 2.0 + 1.0; }

void main()
{
    ivec2 full = fg_view_size(pc.view);
    ivec4 rect = fg_level_rect(pc.level, full);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * pc.stride;
    if (pixel.x >= rect.z || pixel.y >= rect.w) return;
    float block = float(1 << pc.level);
    // The footprint's centre in full-resolution pixels; an edge block may reach past the image.
    vec2 centre = (vec2(pixel) + 0.5) * block;
    if (pc.level == 0 && !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, centre / vec2(full), vec2(pc.level == 0 ? 0.0 : block) / vec2(full))) {
        imageStore(fg_levels, rect.xy + pixel, vec4(pc.level == 0 ? FG_MISS : fg_escaped(), fg_escaped(), 0.0, 0.0));
        if (pc.level == 0) {
            imageStore(fg_depth, pixel, vec4(FG_MISS));
#ifdef FG_HAS_GLOW
            imageStore(fg_glow, pixel, vec4(1e30));
#endif
        }
        return;
    }
    vec3 ro = fg_ray_origin(pc.view, centre / vec2(full));
    vec3 rd = fg_ray_dir(pc.view, centre / vec2(full));
    float spread = fg_origin_spread(pc.view, pc.level);
    float parent = fg_bounds_interval_spread(ro, rd, fg_cone_tan(pc.level), spread).x;
    if (pc.top == 0) {
        ivec4 up = fg_level_rect(pc.level + 1, full);
        parent = imageLoad(fg_levels, up.xy + pixel / 2).y;
    }
    uint evaluations = 0u;

    if (pc.level > 0) {
        // Coarse level: advance while the whole cone is provably empty.
        float cone = fg_cone_tan(pc.level);
        vec2 range = fg_bounds_interval_spread(ro, rd, cone, spread);
        float t = max(parent, range.x);
        bool touched = false;
        for (int i = 0; i < FG_CONE_STEPS && t <= range.y; ++i) {
            float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
            evaluations++;
            float radius = cone * t + spread;
            // Stepping approaches d = radius only geometrically: stop a little before it.
            if (d <= FG_CONE_STOP * radius) {
                touched = true;
                break;
            }
            // Every ray of the cone stays inside the empty ball for this step.
            t += (d - radius) / (1.0 + cone);
        }
        if (!touched && t > range.y) t = fg_escaped();
        imageStore(fg_levels, rect.xy + pixel, vec4(t, t, 0.0, 0.0));
    } else {
        // Full resolution: the pixel's own ray from the parent's bound, with the hit rule.
        vec2 range = fg_bounds_interval(ro, rd, 0.0);
        float cone = fg_cone_tan(0) * fg_footprint(pc.view, pixel);
        float t = max(parent, range.x);
        float bound = fg_escaped();   // where the pixel's cone first touched
        float result = FG_MISS;
        float closest = 1e30;
        bool deferred = false;
        if (range.x <= range.y && t <= range.y) {
            bool hit = false;
            int i = 0;
            float previous = 0.0;
            float step = 0.0;
            float omega = FG_OVERRELAX;
            for (; i < FG_FINE_STEPS; ++i) {
                if (fg_defer(i)) {
                    deferred = true;
                    // Every step so far kept the cone safe if the bound is still open.
                    bound = min(bound, t);
                    fg_tail_append(pixel, t, closest, uint(i));
                    break;
                }
                float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
                evaluations++;
                // Over-relaxation (Keinert et al.): if the spheres stop overlapping, step back.
                if (omega > 1.0 && bound <= range.y && d + previous < step) {
                    t -= step - previous;
                    omega = 1.0;
                    step = previous;
                    previous = 0.0;
                    continue;
                }
                closest = min(closest, d);
                float radius = cone * t;
                if (bound > range.y && (pc.view != 2 || d <= FG_CONE_STOP * radius)) bound = t;
                if (d < FG_EPSILON * radius) {
                    hit = true;
                    break;
                }
                previous = d;
                // Until the pixel's cone touches, keep the step safe for the whole cone, so
                // `bound` is a lower bound for every ray of the pixel.
                step = bound > range.y ? (d - radius) / (1.0 + cone) : d * omega;
                t += step;
                if (t > range.y) break;
            }
            if (hit || (i == FG_FINE_STEPS && !FG_MISS_ON_STEP_CAP)) result = t;
            if (result != FG_MISS) bound = min(bound, result);
        }
        imageStore(fg_levels, pixel, vec4(result, bound, 0.0, 0.0));
        if (!deferred) {
            imageStore(fg_depth, pixel, vec4(result));
#ifdef FG_HAS_GLOW
            imageStore(fg_glow, pixel, vec4(closest));
#endif
        }
    }
    if (FG_COUNT_EVALUATIONS) atomicAdd(fg_counters.evaluations[pc.counter_slot], evaluations);
}
