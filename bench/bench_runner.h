#pragma once
// `fgplay bench`: for each view, renders a reference and then every setting of the sweep, in one
// run with the same warm-up: GPU time per pass (median of several frames), SDF evaluations per
// output pixel, and the error against the reference. Writes results.csv, results.md, results.json
// and the plots.
#include <string>
#include <vector>

namespace fg::bench {

struct BenchOptions {
    std::string pack;             // a compiled pack, or empty with `graph`
    std::string graph;            // a graph to compile first
    std::string gallery;          // also report the compile time and pack size of every graph here
    std::string out = "bench-results";
    bool quick = false;
    std::uint32_t size = 0;       // per-eye size; 0: 512 (quick: 128)
    int frames = 0;               // timed frames per setting; 0: 3, 15 on a GPU (quick: 2)
    std::vector<std::string> views;   // subset of afar, filled, grazing, deep_zoom; empty: all (quick: afar, filled)
    std::string device;
    bool plots = true;
    // `--sequence`: head traces at 90 Hz instead (run_sequence_bench, sequence_runner.h), over
    // `scenes` (graphs or packs; empty: the gallery's bulb, box and Kleinian) and `traces` (empty: all).
    bool sequence = false;
    std::vector<std::string> scenes, traces;
    // How a trace's frames are timed: "back-to-back" (then errors and counts on a second pass),
    // "interleaved" (each frame timed, read back and compared in turn) or "auto" (back to back on a GPU).
    std::string timing = "auto";
    // Errors against the strict reference on every Nth frame of a trace (1: every frame). Timings and
    // counts are untouched; at a headset's size the comparisons are most of a GPU run's time.
    int compare_every = 1;
    // `--variant`: per-eye conemarch again with these knobs, "knob=value[,knob=value]" each.
    std::vector<std::string> variants;
};

int run_bench(const BenchOptions& options);

}  // namespace fg::bench
