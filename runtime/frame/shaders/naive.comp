//! pass: naive
//! needs: distance
//! when: always
// The baseline: plain sphere tracing of one eye at full resolution, every pixel on its own. Every
// speed figure is a ratio against this pass, and tests use it as a reference.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform writeonly image2D fg_depth;   // t at the hit, FG_MISS on a miss
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 4, r32f) uniform writeonly image2D fg_glow;    // closest approach of the ray
#endif
layout(set = 0, binding = 5, std430) buffer FgCounters { uint evaluations[]; } fg_counters;
layout(push_constant) uniform FgNaivePush { int view; int counter_slot; int stride; } pc;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * pc.stride;
    ivec2 size = ivec2(fg_frame.size.xy);
    if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_outside_lens(pc.view, pixel)) {
        imageStore(fg_depth, pixel, vec4(FG_MISS));
#ifdef FG_HAS_GLOW
        imageStore(fg_glow, pixel, vec4(1e30));
#endif
        return;
    }
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    vec3 ro = fg_ray_origin(pc.view, uv);
    vec3 rd = fg_ray_dir(pc.view, uv);
    vec2 range = fg_bounds_interval(ro, rd, 0.0);
    float pixel_tan = fg_cone_tan(0) * fg_footprint(pc.view, pixel);
    float result = FG_MISS;
    float closest = 1e30;
    uint evaluations = 0u;
    if (range.x <= range.y) {
        float t = range.x;
        bool hit = false;
        int i = 0;
        for (; i < FG_MAX_STEPS; ++i) {
            float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
            evaluations++;
            closest = min(closest, d);
            if (d < FG_EPSILON * pixel_tan * t) {
                hit = true;
                break;
            }
            t += d;
            if (t > range.y) break;
        }
        if (hit || (i == FG_MAX_STEPS && !FG_MISS_ON_STEP_CAP)) result = t;
    }
    imageStore(fg_depth, pixel, vec4(result));
#ifdef FG_HAS_GLOW
    imageStore(fg_glow, pixel, vec4(closest));
#endif
    if (FG_COUNT_EVALUATIONS) atomicAdd(fg_counters.evaluations[pc.counter_slot], evaluations);
}
