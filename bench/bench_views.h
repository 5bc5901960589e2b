#pragma once
// The views a VR flight actually sees, found for any scene with its CPU twin: the fractal whole
// from afar (the scene camera), the headset filled with fractal, a grazing look along a wall, and
// a deep zoom where the viewer has shrunk a thousandfold. A fractal floating in the void makes
// every method look fast; the other three are where the time goes.
#include <string>
#include <vector>

#include "cpu/cpu_evaluator.h"
#include "frame/stereo_rig.h"
#include "graph/scene_settings.h"

namespace fg::bench {

struct BenchView {
    std::string name;
    HeadPose head;
    double world_scale = 1.0;   // scales the eye separation (and the scene appears that much larger)
};

std::vector<BenchView> make_bench_views(const CpuEvaluator& scene, const SceneSettings& settings);

}  // namespace fg::bench
