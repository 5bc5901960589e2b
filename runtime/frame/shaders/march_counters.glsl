// What a marching pass counts in the counting frame (FG_COUNT_EVALUATIONS, a specialization
// constant, so the timed frames carry none of it): SDF evaluations, and how busy the SIMD lanes
// were. Every iteration of a marching loop adds the subgroup's size to `total` and the lanes that
// evaluated in it to `busy` (subgroup ballots), so busy / total is the lane efficiency: the share of
// lane-iterations that did work rather than wait for the slowest ray of their group. Counter slot s
// is FG_COUNTER_WORDS words from s * FG_COUNTER_WORDS: evaluations, busy, total, for cross-frame
// reuse the rays and the thousandths of each ray that reuse skipped, summed, and the iterations of
// the fractal loops those evaluations ran. An evaluation near a surface runs every iteration of an
// escape-time fractal, one far from it leaves after a few: evaluations alone do not predict time.

layout(set = 0, binding = 12, std430) buffer FgCounters { uint counts[]; } fg_counters;

uint fg_lanes_busy = 0u;
uint fg_lanes_total = 0u;
uint fg_reuse_rays = 0u;
uint fg_reuse_skipped = 0u;
uint fg_fractal_iterations = 0u;

// Every fractal node's loop calls this once per iteration (nodes/prelude.glsl: a no-op elsewhere).
#define FG_COUNTS_FRACTAL_ITERATIONS 1
void fg_count_fractal_iteration()
{
    if (FG_COUNT_EVALUATIONS) fg_fractal_iterations++;
}

// Once per ray that cross-frame reuse could shorten: the share of it that reuse skipped.
void fg_count_reuse(float skipped)
{
    if (!FG_COUNT_EVALUATIONS) return;
    fg_reuse_rays++;
    fg_reuse_skipped += uint(clamp(skipped, 0.0, 1.0) * 1000.0 + 0.5);
}

// Once per loop iteration, by every lane still in the loop.
void fg_count_iteration(bool busy)
{
    if (!FG_COUNT_EVALUATIONS) return;
    uint busy_lanes = subgroupBallotBitCount(subgroupBallot(busy));
    if (subgroupElect()) {
        fg_lanes_busy += busy_lanes;
        fg_lanes_total += gl_SubgroupSize;
    }
}

// Once per invocation, at its end.
void fg_count_flush(int slot, uint evaluations)
{
    if (!FG_COUNT_EVALUATIONS) return;
    uint base = FG_COUNTER_WORDS * uint(slot);
    if (evaluations > 0u) atomicAdd(fg_counters.counts[base], evaluations);
    if (fg_lanes_total > 0u) {
        atomicAdd(fg_counters.counts[base + 1u], fg_lanes_busy);
        atomicAdd(fg_counters.counts[base + 2u], fg_lanes_total);
    }
    if (fg_fractal_iterations > 0u) atomicAdd(fg_counters.counts[base + 5u], fg_fractal_iterations);
    if (fg_reuse_rays > 0u) {
        atomicAdd(fg_counters.counts[base + 3u], fg_reuse_rays);
        atomicAdd(fg_counters.counts[base + 4u], fg_reuse_skipped);
    }
}
