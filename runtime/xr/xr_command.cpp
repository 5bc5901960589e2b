#include "xr/xr_command.h"

#include <cstdio>
#include <fmt/format.h>

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
    c.command->add_option("--budget-ms", c.options.budget_ms, "GPU time per frame to hold (default: the display period)");
    c.command->add_option("--fly", c.options.fly, "fly where you look at this throttle (1 = normal speed)");
    c.command->add_option("--controller-speed", c.options.controller_speed,
                          "throttle of a full trigger pull (flight along the controller's aim)")->capture_default_str();
    c.command->add_flag_function("--no-controllers", [&c](std::int64_t) { c.options.controllers = false; },
                                 "no OpenXR actions: gaze flight only");
    c.command->add_flag_function("--no-wrap", [&c](std::int64_t) { c.options.wrap = false; },
                                 "keep absolute coordinates in looping scenes (to compare)");
    c.command->add_flag("--check-collisions", c.options.check_collisions,
                        "watch the head with the CPU twin of the scene and report how close it came");
    c.command->add_option("--device", c.options.device, "Vulkan device: index or name substring");
}

int XrCommand::run() {
    if (!size.empty()) {
        unsigned w = 0, h = 0;
        if (std::sscanf(size.c_str(), "%ux%u", &w, &h) != 2 || w == 0 || h == 0 || w > 16384 || h > 16384) {
            fmt::print(stderr, "fgplay xr: --size must look like 512x512\n");
            return 2;
        }
        options.width = w;
        options.height = h;
    }
    if (!parse_stereo_mode(stereo, options.stereo)) {
        fmt::print(stderr, "fgplay xr: --stereo is reproject, per-eye or naive, not '{}'\n", stereo);
        return 2;
    }
    for (const auto& k : knobs) {
        auto eq = k.find('=');
        try {
            if (eq == std::string::npos) throw std::invalid_argument(k);
            options.knobs[k.substr(0, eq)] = std::stod(k.substr(eq + 1));
        } catch (const std::exception&) {
            fmt::print(stderr, "fgplay xr: --knob takes name=value, not '{}'\n", k);
            return 2;
        }
    }
    return play_xr(options);
}

}  // namespace fg::xr
