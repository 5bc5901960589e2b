//! pass: naive
//! needs: distance
//! when: always
//! include: march_counters.glsl
//! include: lane_queue.glsl
//! include: march_rays.glsl
//! include: dispatch_tiles.glsl
// The baseline: plain sphere tracing of one eye at full resolution, every pixel on its own. Every
// speed figure is a ratio against this pass, and tests use it as a reference. With
// FG_PERSISTENT_LANES its lanes take pixels from a queue (lane_queue.glsl): the stronger baseline,
// bit-identical frames.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, r32f) uniform writeonly image2D fg_depth;   // t at the hit, FG_MISS on a miss
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 4, r32f) uniform writeonly image2D fg_glow;    // closest approach of the ray
#endif
layout(push_constant) uniform FgNaivePush { NaivePush pc; };

uint fg_evaluations = 0u;

// One pixel's ray, one step at a time.
struct FgNaiveRay {
    ivec2 pixel;
    vec3 ro;
    vec3 rd;
    vec2 range;
    float hit_tan;       // the output pixel's: the hit rule
    float t;
    float closest;
    int i;
    bool marching;
    bool hit;
    bool escaped;
};

FgNaiveRay fg_naive_begin(ivec2 pixel, ivec2 size)
{
    FgNaiveRay r;
    r.pixel = pixel;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
    r.ro = fg_ray_origin(pc.view, uv);
    r.rd = fg_ray_dir(pc.view, uv);
    r.range = fg_bounds_interval(r.ro, r.rd, 0.0);
    r.hit_tan = fg_detail_tan();
    r.t = r.range.x;
    r.closest = 1e30;
    r.i = 0;
    r.hit = false;
    r.escaped = false;
    r.marching = r.range.x <= r.range.y && FG_MAX_STEPS > 0;
    return r;
}

void fg_naive_step(inout FgNaiveRay r)
{
    float d = fg_scene_distance(r.ro + r.rd * r.t) * FG_STEP_SCALE;
    fg_evaluations++;
    r.closest = min(r.closest, d);
    if (d < FG_EPSILON * FG_STEP_FRACTION * r.hit_tan * r.t) {
        r.hit = true;
        r.marching = false;
        return;
    }
    r.t += d;
    r.escaped = r.t > r.range.y;
    r.marching = !r.escaped && ++r.i < FG_MAX_STEPS;
}

void fg_naive_finish(FgNaiveRay r)
{
    bool in_bounds = r.range.x <= r.range.y;
    bool capped = in_bounds && !r.hit && !r.escaped && r.i == FG_MAX_STEPS;
    float result = r.hit || (capped && !FG_MISS_ON_STEP_CAP) ? r.t : FG_MISS;
    if (FG_PERSISTENT_LANES) {
        fg_ray_result(r.pixel, int(fg_frame.eye_size.x), vec4(result, 0.0, r.closest, 0.0));
        return;
    }
    imageStore(fg_depth, r.pixel, vec4(result));
#ifdef FG_HAS_GLOW
    imageStore(fg_glow, r.pixel, vec4(r.closest));
#endif
}

// A pixel outside the lens is never marched: it misses.
bool fg_skip_outside_lens(ivec2 pixel)
{
    if (!fg_outside_lens(pc.view, pixel)) return false;
    imageStore(fg_depth, pixel, vec4(FG_MISS));
#ifdef FG_HAS_GLOW
    imageStore(fg_glow, pixel, vec4(1e30));
#endif
    return true;
}

// Persistent lanes: bursts of marching while most lanes have a ray; between bursts, the rays that
// ended are written (to the rays buffer: resolve.comp moves them into the images) and their lanes
// take new pixels (of this dispatch's stride) from the queue, until it runs dry.
void fg_naive_persistent(ivec2 size)
{
    ivec2 grid = (size + ivec2(pc.stride - 1)) / pc.stride;
    FgNaiveRay r;
    r.marching = false;
    bool ended = false;   // r is a ray that ended and is not written yet
    bool dry = false;
    uint taken = 0u;      // pixels this lane took (FG_LANE_PIXELS)
    while (true) {
        if (ended) fg_naive_finish(r);
        ended = false;
        if (!r.marching && !dry) {
            ivec2 pixel;
            if (fg_lane_takes_pixel(pc.view, pc.stride, grid, dry, taken, pixel)) {
                r = fg_naive_begin(pixel, size);
                ended = !r.marching;
            }
        }
        if (dry && !r.marching && !ended) break;
        while (fg_lanes_burst(r.marching)) {
            fg_count_iteration(r.marching);
            if (r.marching) {
                fg_naive_step(r);
                ended = !r.marching;
            }
        }
    }
}

void main()
{
    ivec2 size = ivec2(fg_frame.eye_size);
    if (FG_PERSISTENT_LANES) {
        fg_naive_persistent(size);
    } else {
        ivec2 pixel = fg_dispatch_cell(pc.stride, fg_invocation_cell());
        if (pixel.x >= size.x || pixel.y >= size.y || !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
        if (fg_skip_outside_lens(pixel)) return;
        FgNaiveRay r = fg_naive_begin(pixel, size);
        while (r.marching) {
            fg_count_iteration(true);
            fg_naive_step(r);
        }
        fg_naive_finish(r);
    }
    fg_count_flush(pc.counter_slot, fg_evaluations);
}
