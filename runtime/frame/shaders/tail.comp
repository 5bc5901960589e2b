//! pass: tail
//! needs: distance
//! when: always
//! include: tail_queue.glsl
//! include: march_counters.glsl
// Finishes the full-resolution march of the pixels the conemarch deferred (FG_TAIL_AFTER): one
// invocation per queued pixel, so the slow tail near surfaces runs in full workgroups instead of
// idling the lanes of pixels that finished early. Dispatched indirectly with the queue's size.

layout(local_size_x = 64) in;
layout(set = 0, binding = 3, rg32f) uniform image2D fg_levels;
layout(set = 0, binding = 5, r32f) uniform writeonly image2D fg_depth;
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 6, r32f) uniform writeonly image2D fg_glow;
#endif
layout(push_constant) uniform FgTailPush { TailPush pc; };

void main()
{
    uint index = gl_GlobalInvocationID.x;
    if (index >= min(fg_tail.count, uint(fg_tail.items.length()))) return;
    FgTailItem item = fg_tail.items[index];
    ivec2 pixel = ivec2(item.pixel & 0xffffu, item.pixel >> 16);
    ivec2 full = fg_view_size(pc.view);
    vec2 uv = (vec2(pixel) + 0.5) / vec2(full);
    vec3 ro = fg_ray_origin(pc.view, uv);
    vec3 rd = fg_ray_dir(pc.view, uv);
    vec2 range = fg_bounds_interval(ro, rd, 0.0);
    float cone = fg_detail_tan();
    float t = item.t;
    float closest = item.closest;
    uint evaluations = 0u;
    bool hit = false;
    int i = int(item.steps);
    float previous = 0.0;
    float step = 0.0;
    float omega = FG_OVERRELAX;
    for (; i < FG_FINE_STEPS; ++i) {
        fg_count_iteration(true);
        float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
        evaluations++;
        if (omega > 1.0 && d + previous < step) {
            t -= step - previous;
            omega = 1.0;
            step = previous;
            previous = 0.0;
            continue;
        }
        closest = min(closest, d);
        if (d < FG_EPSILON * FG_STEP_FRACTION * cone * t) {
            hit = true;
            break;
        }
        previous = d;
        step = d * omega;
        t += step;
        if (t > range.y) break;
    }
    float result = (hit || (i == FG_FINE_STEPS && !FG_MISS_ON_STEP_CAP)) ? t : FG_MISS;
    vec2 level = imageLoad(fg_levels, pixel).xy;
    imageStore(fg_levels, pixel, vec4(result, result == FG_MISS ? level.y : min(level.y, result), 0.0, 0.0));
    imageStore(fg_depth, pixel, vec4(result));
#ifdef FG_HAS_GLOW
    imageStore(fg_glow, pixel, vec4(closest));
#endif
    fg_count_flush(pc.counter_slot, evaluations);
}
