//! pass: conemarch
//! needs: distance
//! when: always
//! include: tail_queue.glsl
//! include: march_counters.glsl
//! include: lane_queue.glsl
//! include: march_rays.glsl
//! include: cone_walk.glsl
//! include: dispatch_tiles.glsl
// Progressive cone marching (Fulcrum's Fractus, Framestore's VR fractals), one dispatch per level
// from coarse to fine. A level-k pixel marches a cone that covers its 2^k x 2^k footprint, starting
// where its parent stopped, and stops as soon as the cone may touch a surface: its distance is a
// lower bound for every ray in its footprint, so the next level can start there. Level 0 marches
// the pixel's own ray to the hit, and also records where the pixel's cone first touched (a lower
// bound for the whole pixel), which stereo reprojection uses.
//
// The levels of a view live in one atlas image (see fg_level_rect): x = depth (level 0: the hit or
// FG_MISS; coarser: the cone's lower bound), y = the cone's lower bound.
//
// Level 0 runs one invocation per pixel, or with FG_PERSISTENT_LANES a fixed set of workgroups
// whose lanes take pixels from a queue (lane_queue.glsl): the same march, step for step.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, rg32f) uniform image2D fg_levels;
layout(set = 0, binding = 5, r32f) uniform writeonly image2D fg_depth;     // level 0: the eye's depth image
#ifdef FG_HAS_GLOW
layout(set = 0, binding = 6, r32f) uniform writeonly image2D fg_glow;      // level 0: closest approach
#endif
layout(push_constant) uniform FgConePush { ConemarchPush pc; };

// What this dispatch marches: the runtime makes one pipeline per level kind and view kind
// (dispatch constants), so each runs only its own code; -1 reads the push constants.
bool fg_full_resolution() { return FG_SPEC_FULL_RESOLUTION >= 0 ? FG_SPEC_FULL_RESOLUTION == 1 : pc.level == 0; }
bool fg_centre_dispatch() { return FG_SPEC_CENTRE_VIEW >= 0 ? FG_SPEC_CENTRE_VIEW == 1 : pc.view == FG_VIEW_CENTRE; }

// Full resolution with FG_TAIL_AFTER > 0: a pixel still marching after that many steps goes to
// the tail queue (tail.comp finishes it).
bool fg_defer(int step) { return FG_TAIL_AFTER > 0 && step == FG_TAIL_AFTER; }

// A bound beyond every ray's exit: children of an escaped cone miss at once.
float fg_escaped() { return fg_scene.far_limit * 2.0 + 1.0; }

uint fg_evaluations = 0u;

// Coarse level: advance while the whole cone is provably empty, from where the parent level or the
// previous frame (cone_walk.glsl) left it.
void fg_march_cone(ivec2 pixel, ivec4 rect, vec3 ro, vec3 rd, float parent, float spread)
{
    float cone = fg_cone_tan(pc.level);
    vec2 range = fg_bounds_interval_spread(ro, rd, cone, spread);
    float t = fg_reused_bound(pc.view, int(pc.level), ro, rd, cone, max(parent, range.x), range.y);
    bool touched = false;
    for (int i = 0; i < FG_CONE_STEPS && t <= range.y; ++i) {
        fg_count_iteration(true);
        float d = fg_scene_distance(ro + rd * t) * FG_STEP_SCALE;
        fg_evaluations++;
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
}

// The full-resolution march of one pixel's own ray, one step at a time, from its parent's bound
// with the hit rule.
struct FgFineRay {
    ivec2 pixel;
    vec3 ro;
    vec3 rd;
    vec2 range;
    float cone;          // the marched pixel's cone, which its samples certify empty
    float hit_tan;       // the output pixel's: the hit rule
    float t;
    float bound;         // where the pixel's cone first touched (the centre eye: its steps keep the cone safe)
    float covered;       // an eye: how far the balls of its samples so far prove the pixel's cone empty
    float start;         // where the march would start without cross-frame reuse (for the counts)
    float resumed;       // where it starts with it
    float closest;
    float previous;
    float step;
    float omega;
    int i;
    bool marching;
    bool hit;
    bool escaped;
    bool deferred;
};

// The parent level's bound for a full-resolution pixel, or where its ray enters the bounds. A pixel
// of the foveated periphery stands for its 2x2 block, as a level-1 cell does, and marches with that
// footprint: the runtime starts it from level 2 (FG_SPEC_PERIPHERY_PARENT), and level 1 then
// covers only the fovea's tiles.
float fg_parent_bound(ivec2 pixel, ivec2 full, vec3 ro, vec3 rd)
{
    int parent = pc.stride == 2 && FG_SPEC_PERIPHERY_PARENT > 1 ? FG_SPEC_PERIPHERY_PARENT : 1;
    if (int(fg_frame.cone_levels) > parent) return imageLoad(fg_levels, fg_level_rect(parent, full).xy + (pixel >> parent)).y;
    return fg_bounds_interval_spread(ro, rd, fg_cone_tan(0), fg_origin_spread(pc.view, 0)).x;
}

FgFineRay fg_fine_begin(ivec2 pixel, ivec2 full)
{
    FgFineRay r;
    r.pixel = pixel;
    vec2 uv = (vec2(pixel) + 0.5) / vec2(full);
    r.ro = fg_ray_origin(pc.view, uv);
    r.rd = fg_ray_dir(pc.view, uv);
    float parent = fg_parent_bound(pixel, full, r.ro, r.rd);
    r.range = fg_bounds_interval(r.ro, r.rd, 0.0);
    // A periphery pixel stands for its 2x2 block when certifying its cone, but it hits by the output
    // pixel like every other, so the periphery shows the same fractal as the fovea.
    r.cone = fg_cone_tan(0) * (pc.stride == 2 ? 2.0 : 1.0);
    r.hit_tan = fg_detail_tan();
    // The parent's cone holds this pixel's cone, and the previous frame may prove more of it.
    r.covered = fg_reused_bound(pc.view, 0, r.ro, r.rd, r.cone, parent, r.range.y);
    r.t = max(r.covered, r.range.x);
    r.start = max(parent, r.range.x);
    r.resumed = r.t;
    // An eye's march keeps its cone safe for no step (fg_cover certifies the cone instead): its bound
    // closes where it starts. The centre eye's stays open until its cone may touch.
    r.bound = fg_centre_dispatch() ? fg_escaped() : r.t;
    r.closest = 1e30;
    r.previous = 0.0;
    r.step = 0.0;
    r.omega = FG_OVERRELAX;
    r.i = 0;
    r.hit = false;
    r.escaped = false;
    r.deferred = false;
    r.marching = r.range.x <= r.range.y && r.t <= r.range.y && FG_FINE_STEPS > 0;
    return r;
}

// An eye marches its own ray with plain steps, and its samples still certify its pixel's cone: the
// ball of radius d at t holds every point of the cone (radius c t' + s, s the spread of the rays'
// origins in ODS) at t' with |t' - t| + c t' + s <= d, that is t' in [(t - d + s) / (1 - c),
// (t + d - s) / (1 + c)]. Where that reaches back to what is covered already, the cover grows: the
// pixel's own cone bound, which an eye's level 0 records. Returns d.
float fg_cover(inout FgFineRay r, float d)
{
    float s = fg_origin_spread(pc.view, 0);
    if ((r.t - d + s) / (1.0 - r.cone) <= r.covered) r.covered = max(r.covered, (r.t + d - s) / (1.0 + r.cone));
    return d;
}

// Hands a ray that is still marching after FG_TAIL_AFTER steps to the tail pass.
void fg_fine_defer(inout FgFineRay r)
{
    r.deferred = true;
    // Every step so far kept the cone safe if the bound is still open.
    r.bound = min(r.bound, r.t);
    fg_tail_append(r.pixel, r.t, r.closest, uint(r.i));
    r.marching = false;
}

void fg_fine_step(inout FgFineRay r)
{
    float d = fg_scene_distance(r.ro + r.rd * r.t) * FG_STEP_SCALE;
    fg_evaluations++;
    // Over-relaxation (Keinert et al.): if the spheres stop overlapping, step back. The knob is a
    // specialization constant, so without it the check costs nothing; every test of a step costs
    // all SIMD lanes on a CPU rasteriser.
    if (FG_OVERRELAX > 1.0 && r.omega > 1.0 && r.bound <= r.range.y && d + r.previous < r.step) {
        r.t -= r.step - r.previous;
        r.omega = 1.0;
        r.step = r.previous;
        r.previous = 0.0;
        r.marching = ++r.i < FG_FINE_STEPS;
        return;
    }
    // Only a later frame's reuse reads an eye's own cone bound: without it the eye records its
    // parent's, and its steps skip the certificate (a tenth of level 0's time on lavapipe).
    r.closest = min(r.closest, FG_REUSE ? fg_cover(r, d) : d);
    float radius = r.cone * r.t;
    // Until the centre eye's cone touches, its steps stay safe for the whole cone, so `bound` is a
    // lower bound for every ray of the pixel. The eyes' pipelines drop this code.
    bool cone_safe = false;
    if (fg_centre_dispatch()) {
        if (r.bound > r.range.y && d <= FG_CONE_STOP * radius) r.bound = r.t;
        cone_safe = r.bound > r.range.y;
    }
    if (d < FG_EPSILON * FG_STEP_FRACTION * r.hit_tan * r.t) {
        r.hit = true;
        r.marching = false;
        return;
    }
    r.previous = d;
    r.step = cone_safe ? (d - radius) / (1.0 + r.cone) : d * r.omega;
    r.t += r.step;
    r.escaped = r.t > r.range.y;
    r.marching = !r.escaped && ++r.i < FG_FINE_STEPS;
}

void fg_fine_finish(FgFineRay r)
{
    float result = FG_MISS;
    float bound = fg_centre_dispatch() ? r.bound : r.covered;
    bool capped = !r.hit && !r.escaped && !r.deferred && r.i == FG_FINE_STEPS;
    if (r.hit || (capped && !FG_MISS_ON_STEP_CAP)) result = r.t;
    if (result != FG_MISS) bound = min(bound, result);
    // How much of the march reuse skipped: from where it would have started to where it ended.
    if (FG_REUSE && r.range.x <= r.range.y) fg_count_reuse(r.t > r.start ? (min(r.resumed, r.t) - r.start) / (r.t - r.start) : 0.0);
    if (FG_PERSISTENT_LANES) {
        fg_ray_result(r.pixel, fg_view_size(pc.view).x, vec4(result, bound, r.closest, 0.0));
        return;
    }
    imageStore(fg_levels, r.pixel, vec4(result, bound, 0.0, 0.0));
    if (!r.deferred) {
        imageStore(fg_depth, r.pixel, vec4(result));
#ifdef FG_HAS_GLOW
        imageStore(fg_glow, r.pixel, vec4(r.closest));
#endif
    }
}

// A pixel outside the lens is never marched: it misses, at every level.
bool fg_skip_outside_lens(ivec2 pixel, ivec4 rect, ivec2 full)
{
    float block = float(1 << pc.level);
    vec2 centre = (vec2(pixel) + 0.5) * block;
    if (!fg_outside_lens(pc.view, centre / vec2(full), vec2(fg_full_resolution() ? 0.0 : block) / vec2(full))) return false;
    // y: children of a hidden block are hidden too and never read it; a later frame's reuse must not
    // take a cell that was never marched as empty.
    imageStore(fg_levels, rect.xy + pixel, vec4(fg_full_resolution() ? FG_MISS : fg_escaped(), 0.0, 0.0, 0.0));
    if (fg_full_resolution()) {
        imageStore(fg_depth, pixel, vec4(FG_MISS));
#ifdef FG_HAS_GLOW
        imageStore(fg_glow, pixel, vec4(1e30));
#endif
    }
    return true;
}

// Persistent lanes: bursts of marching while most lanes have a ray; between bursts, the rays that
// ended are written (to the rays buffer: resolve.comp moves them into the images) and their lanes
// take new pixels (of this dispatch's stride) from the queue, until it runs dry.
void fg_fine_persistent(ivec2 size)
{
    ivec2 grid = (size + ivec2(pc.stride - 1)) / pc.stride;
    FgFineRay r;
    r.marching = false;
    bool ended = false;   // r is a ray that ended and is not written yet
    bool dry = false;
    uint taken = 0u;      // pixels this lane took (FG_LANE_PIXELS)
    while (true) {
        if (ended) fg_fine_finish(r);
        ended = false;
        if (!r.marching && !dry) {
            ivec2 pixel;
            if (fg_lane_takes_pixel(pc.view, pc.stride, grid, dry, taken, pixel)) {
                r = fg_fine_begin(pixel, size);
                ended = !r.marching;
            }
        }
        if (dry && !r.marching && !ended) break;
        while (fg_lanes_burst(r.marching)) {
            fg_count_iteration(r.marching);
            if (r.marching) {
                fg_fine_step(r);
                ended = !r.marching;
            }
        }
    }
}

void main()
{
    ivec2 full = fg_view_size(pc.view);
    if (fg_full_resolution() && FG_PERSISTENT_LANES) {
        fg_fine_persistent(full);
        fg_count_flush(pc.counter_slot, fg_evaluations);
        return;
    }
    ivec4 rect = fg_level_rect(fg_full_resolution() ? 0 : pc.level, full);
    ivec2 pixel = fg_dispatch_cell(pc.stride, fg_invocation_cell());
    if (pixel.x >= rect.z || pixel.y >= rect.w) return;
    if (fg_full_resolution() && !fg_dispatch_takes(pc.view, pixel, pc.stride)) return;
    if (fg_skip_outside_lens(pixel, rect, full)) return;
    if (!fg_full_resolution()) {
        float block = float(1 << pc.level);
        vec2 uv = (vec2(pixel) + 0.5) * block / vec2(full);
        vec3 ro = fg_ray_origin(pc.view, uv);
        vec3 rd = fg_ray_dir(pc.view, uv);
        float spread = fg_origin_spread(pc.view, pc.level);
        float parent = pc.top == 0 ? imageLoad(fg_levels, fg_level_rect(pc.level + 1, full).xy + pixel / 2).y
                                   : fg_bounds_interval_spread(ro, rd, fg_cone_tan(pc.level), spread).x;
        fg_march_cone(pixel, rect, ro, rd, parent, spread);
    } else {
        FgFineRay r = fg_fine_begin(pixel, full);
        // The deferral comes after the loop, not in its step: llvmpipe runs every branch of a loop's
        // body in all lanes, taken or not, so an append in the step costs its atomics every step.
        while (r.marching && !fg_defer(r.i)) {
            fg_count_iteration(true);
            fg_fine_step(r);
        }
        if (r.marching) fg_fine_defer(r);
        fg_fine_finish(r);
    }
    fg_count_flush(pc.counter_slot, fg_evaluations);
}
