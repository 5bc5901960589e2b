#pragma once
// `fgplay bench --sequence`: what a headset renders, measured. Every scene flies every head trace
// (head_trace.h) at 90 Hz through every setting (sequence_settings.h). One timed renderer per
// (scene, setting) renders each trace's frames in order and keeps its executor across frames and
// traces, as a headset's would; a second renderer with evaluation counting on samples every few
// frames; a strict reference renders every frame once per trace. The settings take turns frame by
// frame, so the load of a shared machine falls on all of them alike. Writes sequence.csv,
// sequence_frames.csv, sequence.md and the plots.
#include "bench_runner.h"

namespace fg::bench {

int run_sequence_bench(const BenchOptions& options);

}  // namespace fg::bench
