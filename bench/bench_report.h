#pragma once
// Benchmark results: one row per (view, setting), written as CSV, Markdown and JSON, plotted by
// bench/plot_bench.py, and summed up in one line.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "frame/frame_settings.h"

namespace fg::bench {

struct BenchRow {
    std::string view, setting, group, stereo;
    bool baseline = false;
    std::uint32_t size = 0;
    FrameSettings frame;                     // what was rendered: results.json carries it for the frame governor
    std::map<std::string, double> pass_ms;   // per timer group and "frame"; median of the timed frames
    double evaluations_per_pixel = 0.0;
    bool comparable = true;
    double misclassified_pct = 0.0, depth_median = 0.0, depth_p95 = 0.0, psnr = 0.0;
    std::size_t not_finite = 0, overstepped = 0;
    std::size_t reference_cpu_checked = 0, reference_cpu_disagree = 0;
    double time_speedup = 0.0, evaluation_speedup = 0.0;   // baseline / this, same view
    int sm_clock_mhz = -1;   // an NVIDIA GPU's shader clock just after the timed frames (NVML); -1 unread
    std::string error;

    double frame_ms() const;
    std::string brief() const;
};

struct CompileFigure {
    std::string graph;
    double cold_ms = 0.0, warm_ms = 0.0;
    std::size_t pack_bytes = 0;
};

struct BenchReport {
    std::string scene, device;
    std::uint32_t size = 0;
    int frames = 0;
    std::vector<BenchRow> rows;
    std::vector<CompileFigure> compile;
    unsigned max_sm_mhz = 0;   // the GPU's highest shader clock where NVML reads it, else 0

    void fill_ratios();
    void write(const std::string& folder) const;
    void plot(const std::string& folder) const;
    // The best setting within 0.5 % misclassified pixels of the baseline in every view: its speed-up in time and in
    // evaluations over the baseline, summed over the views.
    std::string summary_line() const;
};

std::string file_safe(std::string name);

}  // namespace fg::bench
