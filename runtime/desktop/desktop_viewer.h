#pragma once
// `fgplay view`: a pack (or a graph, recompiled on save with --watch) in a desktop window.
// Mouse-look with the left button held, WASD/QE to fly, the scroll wheel for speed, B for the
// side-by-side stereo pair, Left/Right arrows for 90° snap turns (with a fade), -/= to shrink or
// grow yourself (the world scale), Esc to quit. The title bar shows per-pass GPU times and, with
// --budget-ms, the frame governor's level.
#include <cstdint>
#include <string>
#include <vector>

#include "frame/frame_settings.h"

namespace fg::desktop {

struct ViewOptions {
    std::string path;                     // .fgpack or graph .json
    bool watch = false;
    int frames = 0;                       // quit after this many frames (tests); 0 = until closed
    std::uint32_t width = 256, height = 256;   // per eye
    StereoMode stereo = StereoMode::PerEye;
    bool side_by_side = false;
    std::string screenshot;               // PNG of the window's last frame
    bool validation = false;
    std::string device;
    // Scripted input for tests: fly forward at this throttle (1 = the distance-proportional speed).
    double autopilot = 0.0;
    bool check_collisions = false;        // watch the head with the CPU twin and report
    // Scripted keys for tests: "KEY@FIRST-LAST" frames held (KEY: left, right, shrink, grow).
    std::vector<std::string> press;
    // Holding a frame budget: the governor of `fgplay xr` (0: off), on the fixed ladder or on the
    // Pareto front `fgplay bench` measured (its results.json).
    double budget_ms = 0.0;
    std::string trade_offs;
    // Temporal anti-aliasing: jittered rays blended into a history; a still view refines to 16
    // samples per pixel and then renders nothing until it moves.
    bool taa = false;
};

int view(const ViewOptions& options);

}  // namespace fg::desktop
