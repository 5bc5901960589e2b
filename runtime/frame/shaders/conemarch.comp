//! pass: conemarch
//! needs: distance
//! when: always
// Progressive cone marching (Fulcrum's Fractus, Framestore's VR fractals), one dispatch per level
// from coarse to fine. A level-k pixel marches a cone that covers its 2^k x 2^k footprint, starting
// where its parent stopped, and stops as soon as the cone may touch a surface: so its distance is a
// lower bound for every ray in its footprint, and the next level can start there. Level 0 is the
// full-resolution march with the hit rule.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform readonly image2D fg_parent;   // level + 1 (unused at the top)
layout(set = 0, binding = 4, r32f) uniform writeonly image2D fg_level;   // this level
layout(set = 0, binding = 5, std430) buffer FgCounters { uint evaluations[]; } fg_counters;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 6, r32f) uniform writeonly image2D fg_glow;    // level 0 only
#endif
layout(push_constant) uniform FgConePush {
    int view;
    int level;           // 0 = full resolution
    int top;             // 1 for the coarsest level: no parent
    int counter_slot;
} pc;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(fg_level);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    ivec2 full = ivec2(fg_frame.size.xy);
    float block = float(1 << pc.level);
    // The footprint's centre in full-resolution pixels, clamped to the image for edge blocks.
    vec2 centre = min((vec2(pixel) + 0.5) * block, vec2(full));
    vec2 uv = centre / vec2(full);
    vec3 ro = fg_ray_origin(pc.view);
    vec3 rd = fg_ray_dir(pc.view, uv);
    float cone = fg_cone_tan(pc.level) * (pc.level == 0 ? 1.0 : FG_CONE_SCALE);
    vec2 range = fg_bounds_interval(ro, rd, cone);
    float far = fg_scene.misc.y;
    float t = pc.top != 0 ? range.x : imageLoad(fg_parent, pixel / 2).x;
    uint evaluations = 0u;
    float result;

    if (pc.level > 0) {
        // Coarse level: advance while the whole cone is provably empty.
        if (range.x > range.y) {
            t = far * 2.0;
        } else {
            t = max(t, range.x);
            for (int i = 0; i < FG_CONE_STEPS && t <= range.y; ++i) {
                float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
                evaluations++;
                float radius = cone * t;
                if (d <= radius) break;
                // Every ray of the cone stays inside the empty ball for this step.
                t += (d - radius) / (1.0 + cone);
            }
            if (t > range.y) t = far * 2.0;
        }
        result = t;
    } else {
        // Full resolution: the pixel's own ray, from the lower bound, with the hit rule.
        result = FG_MISS;
        float closest = 1e30;
        if (range.x <= range.y && t <= range.y) {
            t = max(t, range.x);
            bool hit = false;
            int i = 0;
            float previous = 0.0;
            float step = 0.0;
            float omega = FG_OVERRELAX;
            for (; i < FG_FINE_STEPS; ++i) {
                float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
                evaluations++;
                // Over-relaxation (Keinert et al.): if the spheres stop overlapping, step back.
                if (omega > 1.0 && d + previous < step) {
                    t -= step - previous;
                    omega = 1.0;
                    step = previous;
                    continue;
                }
                closest = min(closest, d);
                if (d < FG_EPSILON * cone * t) {
                    hit = true;
                    break;
                }
                previous = d;
                step = d * omega;
                t += step;
                if (t > range.y) break;
            }
            if (hit || (i == FG_FINE_STEPS && !FG_MISS_ON_STEP_CAP)) result = t;
        }
#ifdef FG_HAS_GLOW
        imageStore(fg_glow, pixel, vec4(closest));
#endif
    }
    imageStore(fg_level, pixel, vec4(result));
    if (FG_COUNT_EVALUATIONS) atomicAdd(fg_counters.evaluations[pc.counter_slot], evaluations);
}
