#pragma once
// Results of `fgplay bench --sequence`: one row per (scene, trace, setting) with its frames kept,
// written as sequence.csv, sequence_frames.csv (every frame) and sequence.md, plotted by
// bench/plot_sequence.py.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frame/frame_executor.h"
#include "sequence_settings.h"

namespace fg::bench {

struct SequenceFrame {
    int index = 0;
    bool dark = false;     // brightness 0: nothing rendered, nothing measured
    double gpu_ms = 0.0;   // FrameStats.gpu_ms "frame" of the timed renderer
    double after_march_ms = 0.0;   // of it, the passes after the march: shade, post, fovea
    bool compared = false;   // against the strict reference (every frame, or every --compare-every'th)
    // ... its depths too (not where temporal upsampling marched fewer pixels than the reference)
    bool depths_compared = false;
    double misclassified_pct = 0.0, overstepped_pct = 0.0, psnr = 0.0;   // against the strict reference
    double overstepped_march_pct = 0.0;   // of the oversteps, at pixels the eye marched (not foveation's fill)
    // Against the picture's ground truth, 16 jittered samples per pixel of naive tracing at the output
    // detail: PSNR, and flicker (frame_measures.h) where the frame before was compared too (< 0: not).
    double picture_psnr = 0.0, flicker = -1.0;
    std::size_t not_finite = 0;
    double evaluations_per_pixel = -1.0;   // from the counting renderer; < 0 on frames it skipped
    double iterations_per_pixel = -1.0;    // fractal loop iterations, the same way
    double sm_clock_mhz = -1.0;            // the GPU's shader clock just after the timed frame; < 0 unknown
};

struct SequenceRow {
    std::string scene, trace;
    SequenceSetting setting;
    std::vector<SequenceFrame> frames;
    std::vector<std::string> counter_groups;   // of the counting frames: one lane column each
    std::map<std::string, LaneCount> lanes;    // summed over the counting frames; empty where not counted
    double reuse_skipped_fraction = 0.0;       // of each level-0 ray, skipped through cross-frame reuse (mean)
    double reuse_skipped_sum = 0.0;            // over the counted frames, to make the mean
    int reuse_skipped_frames = 0;
    // Over the frames rendered (not dark): filled by summarize().
    double median_ms = 0.0, p99_ms = 0.0, worst_ms = 0.0, evaluations_per_pixel = 0.0, iterations_per_pixel = 0.0;
    double after_march_share = 0.0;   // median over frames of after_march_ms / gpu_ms
    // The depths' measures: NaN where no frame's depths were compared (depths_compared).
    double misclassified_mean = 0.0, misclassified_worst = 0.0, overstepped_mean = 0.0, overstepped_worst = 0.0;
    double overstepped_march_mean = 0.0, overstepped_march_worst = 0.0;
    double psnr_mean = 0.0, psnr_worst = 0.0;
    double picture_psnr_median = 0.0, picture_psnr_worst = 0.0, flicker_median = 0.0, flicker_worst = 0.0;
    std::size_t not_finite_worst = 0;
    int rendered = 0, dark = 0, counted = 0;
    // Baseline time / this time, same scene, trace and pixel set; 0 where the baseline is missing.
    double speedup_median_naive = 0.0, speedup_p99_naive = 0.0;
    double speedup_median_naive_lanes = 0.0, speedup_p99_naive_lanes = 0.0;
    std::string error;

    void summarize();
    std::string brief() const;
};

struct SequenceReport {
    std::string device;
    std::uint32_t size = 0;
    int frames = 0, count_every = 1;
    // How busy the machine was: timings on a CPU device (lavapipe) share its cores with everything else.
    double load_start = -1.0, load_end = -1.0, wall_s = 0.0;
    bool back_to_back = false;   // a trace's timed frames ran back to back, its errors and counts after
    int compare_every = 1;       // errors against the reference on every Nth frame (--compare-every)
    unsigned max_sm_mhz = 0;     // the GPU's highest shader clock; 0: not known (no NVML)
    std::vector<std::pair<std::string, std::string>> traces;   // name, motion
    std::vector<SequenceRow> rows;

    void fill_speedups();
    void write(const std::string& folder) const;
    void plot(const std::string& folder) const;
    // Per scene and trace: per-eye conemarch against naive, median and p99, on all pixels and masked.
    std::string headline() const;
};

}  // namespace fg::bench
