#pragma once
// `fgplay xr`: a pack played in an OpenXR headset. The session's predicted display time and view
// poses drive the frame graph; each eye's final image is blitted into that eye's swapchain and
// submitted as a projection layer.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frame/frame_settings.h"
#include "frame/frame_governor.h"

namespace fg::xr {

struct XrPlayOptions {
    std::string pack;
    int frames = 0;                      // end the session after this many frames; 0 = when the runtime ends it
    std::uint32_t width = 0, height = 0; // render size per eye; 0 = the runtime's recommended size
    StereoMode stereo = StereoMode::PerEye;
    std::uint32_t cone_levels = 5;
    bool validation = false;             // Vulkan validation; errors (and OpenXR validation errors) fail the run
    std::string device;
    std::map<std::string, double> knobs;
    bool governor = true;                // hold the frame budget by moving along the accuracy ladder
    bool dynamic_resolution = true;      // with it, the render scale moves in small steps first
    double budget_ms = 0.0;              // 0 = the display period the runtime predicts
    std::string trade_offs;              // results.json of `fgplay bench`: the governor walks its Pareto front
    std::vector<GovernorLevel> ladder;   // read from trade_offs by play_xr; empty: the fixed ladder
    double fly = 0.0;                    // gaze-directed flight at this throttle (1 = normal speed)
    bool check_collisions = false;       // watch the head with the CPU twin and report
    bool controllers = true;             // controller input through OpenXR actions
    double controller_speed = 1.0;       // the trigger's full pull, as a throttle
    bool wrap = true;                    // wrap the head by whole periods in looping scenes
    bool taa = false;                    // temporal anti-aliasing (static scenes)
    double taa_upscale = 1.0;            // with it, temporal upsampling from 1/this of the size per axis
    double taa_sharpen = kTaaSharpen;    // with it, sharpening of slowly moving history
    std::string frame_times;             // CSV file: each frame's wall time, predicted period, GPU time and setting
    std::string record;                  // folder: each submitted frame's eyes as PNG, as fgplay render writes them
};

// Exit codes: 0 clean, 1 error (no runtime, validation errors, ...), 2 the session was lost.
int play_xr(const XrPlayOptions& options);

}  // namespace fg::xr
