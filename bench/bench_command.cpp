#include "bench_command.h"

#include <fmt/format.h>

#include "sequence_runner.h"

namespace fg::bench {

void add_bench_command(CLI::App& app, BenchCommand& c) {
    BenchOptions& b = c.options;
    CLI::App* bench = c.command = app.add_subcommand("bench", "accuracy versus time: sweep the knobs, compare with a reference");
    bench->add_option("pack", b.pack, "shader pack (or --graph)");
    bench->add_option("--graph", b.graph, "compile this graph first (and report its compile time)");
    bench->add_option("--compile-gallery", b.gallery, "also report compile time and pack size of every graph in this folder");
    bench->add_option("--out", b.out, "output folder")->capture_default_str();
    bench->add_flag("--quick", b.quick, "a couple of minutes on two cores: 128x128, two views, a few settings");
    bench->add_option("--size", b.size, "per-eye size (default 512, quick 128)");
    bench->add_option("--frames", b.frames, "timed frames per setting (default 3, 15 on a GPU, quick 2)");
    bench->add_option("--view", b.views, "afar, filled, grazing, deep_zoom (repeatable; default all)");
    bench->add_option("--device", b.device, "Vulkan device: index or name substring");
    bench->add_flag("--no-plots", c.no_plots, "skip the matplotlib plots");
    bench->add_flag("--sequence", b.sequence, "head traces at 90 Hz per scene and setting (--frames per trace, default 90)");
    bench->add_option("--trace", b.traces, "with --sequence: look_around, walk, fast_turn, flight, snap_turn (repeatable)");
    bench->add_option("--scene", b.scenes, "with --sequence: a graph or pack (repeatable; default the gallery's bulb, box, Kleinian)");
    bench->add_option("--timing", b.timing,
                      "with --sequence: back-to-back (timed frames first, errors and counts after: a GPU keeps its "
                      "clock), interleaved (each frame timed and compared in turn), auto (back-to-back unless the "
                      "device is a CPU)")
        ->check(CLI::IsMember({"auto", "back-to-back", "interleaved"}))
        ->capture_default_str();
    bench->add_option("--compare-every", b.compare_every,
                      "with --sequence: errors against the strict reference on every Nth frame only (at a headset's "
                      "size the comparisons take most of a GPU run); timings and counts stay per frame")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    bench->add_option("--variant", b.variants,
                      "with --sequence: also per-eye conemarch with these knobs, on each pixel set: "
                      "knob=value[,knob=value] (repeatable; e.g. cone_steps=16)");
}

int BenchCommand::run() {
    if (!options.sequence && options.pack.empty() == options.graph.empty()) {
        fmt::print(stderr, "fgplay bench: give a pack or --graph, not both\n");
        return 2;
    }
    options.plots = !no_plots;
    return options.sequence ? run_sequence_bench(options) : run_bench(options);
}

}  // namespace fg::bench
