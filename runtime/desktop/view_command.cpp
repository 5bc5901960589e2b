#include "desktop/view_command.h"

#include <filesystem>
#include <fmt/format.h>

#include "frame/frame_arguments.h"

namespace fg::desktop {

void add_view_command(CLI::App& app, ViewCommand& c) {
    c.command = app.add_subcommand("view", "play a pack, or a graph with --watch, in a desktop window");
    c.command->add_option("pack", c.options.path, "shader pack (.fgpack) or graph (.json)")->required()->check(CLI::ExistingFile);
    c.command->add_flag("--watch", c.options.watch, "recompile the graph when it is saved; errors do not stop the preview");
    c.command->add_option("--frames", c.options.frames, "quit after this many frames");
    c.command->add_option("--size", c.size, "per-eye size WxH (the window is two eyes wide)")->capture_default_str();
    c.command->add_option("--stereo", c.stereo, "reproject | per-eye | naive")->capture_default_str();
    c.command->add_flag("--side-by-side", c.options.side_by_side, "start with both eyes side by side (key B toggles)");
    c.command->add_option("--screenshot", c.options.screenshot, "write the window's last frame to this PNG");
    c.command->add_option("--autopilot", c.options.autopilot, "fly forward at this throttle, 1 = normal speed (tests)");
    c.command->add_option("--press", c.options.press,
                          "scripted keys (tests): KEY@FIRST-LAST frames held, KEY one of left, right, shrink, grow");
    c.command->add_flag("--taa", c.options.taa,
                        "temporal anti-aliasing: jittered rays blended into a history; a still view refines to 16 "
                        "samples per pixel, then idles");
    c.command->add_flag("--check-collisions", c.options.check_collisions,
                        "watch the head with the CPU twin of the scene and report how close it came");
    c.command->add_option("--budget-ms", c.options.budget_ms,
                          "hold the GPU time of a frame under this budget with the frame governor (0: off)")->check(CLI::NonNegativeNumber);
    c.command->add_option("--trade-offs", c.options.trade_offs,
                          "with --budget-ms: the governor walks the Pareto front in this `fgplay bench` results.json")
        ->check(CLI::ExistingFile);
    c.command->add_flag("--validation", c.options.validation, "Vulkan validation layer on; errors fail the run");
    c.command->add_option("--device", c.options.device, "Vulkan device: index or name substring");
}

int ViewCommand::run() {
    std::string error;
    if (!parse_size(size, 8192, options.width, options.height, error) || !parse_stereo(stereo, options.stereo, error)) {
        fmt::print(stderr, "fgplay view: {}\n", error);
        return 2;
    }
    if (options.watch && std::filesystem::path(options.path).extension() != ".json") {
        fmt::print(stderr, "fgplay view: --watch needs a graph (.json) to recompile, not a pack\n");
        return 2;
    }
    return view(options);
}

}  // namespace fg::desktop
