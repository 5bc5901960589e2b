#include "xr/xr_command.h"

#include <fmt/format.h>

#include "frame/frame_arguments.h"

namespace fg::xr {

void add_xr_command(CLI::App& app, XrCommand& c) {
    c.command = app.add_subcommand("xr", "play a pack in an OpenXR headset (XR_KHR_vulkan_enable2)");
    c.command->add_option("pack", c.options.pack, "shader pack")->required()->check(CLI::ExistingFile);
    c.command->add_option("--frames", c.options.frames, "end the session cleanly after this many frames");
    c.command->add_option("--size", c.size, "render size per eye WxH (default: the runtime's recommendation)");
    c.command->add_option("--stereo", c.stereo, "reproject | per-eye | naive")->capture_default_str();
    c.command->add_option("--levels", c.options.cone_levels, "conemarch levels")->capture_default_str();
    c.command->add_option("--knob", c.knobs, "override an accuracy knob: name=value");
    c.command->add_flag("--validation", c.options.validation,
                        "Vulkan validation layer on; its errors and OpenXR validation errors fail the run");
    c.command->add_flag_function("--no-governor", [&c](std::int64_t) { c.options.governor = false; },
                        "keep the settings fixed instead of holding the frame budget");
    c.command->add_option("--trade-offs", c.options.trade_offs,
                          "results.json of `fgplay bench` for this graph: the governor walks its measured Pareto front")
        ->check(CLI::ExistingFile);
    c.command->add_flag_function("--no-dynamic-resolution", [&c](std::int64_t) { c.options.dynamic_resolution = false; },
                                 "the governor moves only along its ladder, not the render scale in small steps first");
    c.command->add_option("--budget-ms", c.options.budget_ms, "GPU time per frame to hold (default: the display period)");
    c.command->add_option("--fly", c.options.fly, "fly where you look at this throttle (1 = normal speed)");
    c.command->add_option("--controller-speed", c.options.controller_speed,
                          "throttle of a full trigger pull (flight along the controller's aim)")->capture_default_str();
    c.command->add_flag_function("--no-controllers", [&c](std::int64_t) { c.options.controllers = false; },
                                 "no OpenXR actions: gaze flight only");
    c.command->add_flag_function("--no-wrap", [&c](std::int64_t) { c.options.wrap = false; },
                                 "keep absolute coordinates in looping scenes (to compare)");
    c.command->add_flag("--taa", c.options.taa,
                        "temporal anti-aliasing: jittered rays blended into a history per eye (static scenes)");
    c.command->add_option("--taa-upscale", c.options.taa_upscale,
                          "with --taa: march 1/F of the swapchain's size per axis (1.5 or 2) and resolve to all of it")
        ->capture_default_str()
        ->check(CLI::Range(1.0, 2.0));
    c.command->add_option("--taa-sharpen", c.options.taa_sharpen,
                          "with --taa: how much the shown picture sharpens history moving less than a pixel a frame (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    c.command->add_flag("--check-collisions", c.options.check_collisions,
                        "watch the head with the CPU twin of the scene and report how close it came");
    c.command->add_option("--device", c.options.device, "Vulkan device: index or name substring");
    c.command->add_option("--record", c.options.record,
                          "write each submitted frame's eyes to DIR/left_NNNNNN.png and right_NNNNNN.png (the PNGs "
                          "fgplay render writes)");
    c.command->add_option("--frame-times", c.options.frame_times,
                          "write each frame's wall time (xrBeginFrame to xrEndFrame), predicted display period, GPU time "
                          "and governor setting to this CSV file");
}

int XrCommand::run() {
    std::string error;
    if ((!size.empty() && !parse_size(size, 16384, options.width, options.height, error)) ||
        !parse_stereo(stereo, options.stereo, error) || !parse_knobs(knobs, options.knobs, error)) {
        fmt::print(stderr, "fgplay xr: {}\n", error);
        return 2;
    }
    return play_xr(options);
}

}  // namespace fg::xr
