#pragma once
// Head motion as a headset renders it, 90 frames a second, for `fgplay bench --sequence`: looking
// around, walking, a fast head turn, controller flight and a snap turn. Each trace starts at the
// same pose (the headset filled with fractal, close to its surface) and is made from the scene's
// settings and its CPU twin alone, so the same scene always gives the same poses.
#include <string>
#include <vector>

#include "cpu/cpu_evaluator.h"
#include "frame/stereo_rig.h"
#include "graph/scene_settings.h"

namespace fg::bench {

inline constexpr double kHeadsetHz = 90.0;

struct TraceFrame {
    HeadPose head;
    double time = 0.0;         // seconds since the trace began; also the scene's time
    double brightness = 1.0;   // a snap turn's fade; at 0 the frame renders nothing (as in `fgplay xr`)
};

struct HeadTrace {
    std::string name;     // look_around, walk, fast_turn, flight, snap_turn
    std::string motion;   // what the head does, for the report
    double world_scale = 1.0;
    std::vector<TraceFrame> frames;
};

// Every trace's name, in report order.
const std::vector<std::string>& head_trace_names();

// `frames` frames of every trace from `start`. The twin keeps the walker and the flight out of the
// surface and gives the flight its speed (the scene's locomotion limits: speed proportional to the
// distance, runtime/locomotion/locomotion.h).
std::vector<HeadTrace> make_head_traces(const CpuEvaluator& twin, const SceneSettings& scene, const HeadPose& start,
                                        int frames);

}  // namespace fg::bench
