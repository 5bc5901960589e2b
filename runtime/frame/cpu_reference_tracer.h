#pragma once
// The reference every render is checked against: sphere tracing of one view through the CPU twin
// in double precision, with a tight hit rule and a generous step cap.
#include <cstdint>
#include <vector>

#include "cpu/cpu_evaluator.h"
#include "graph/scene_settings.h"
#include "stereo_rig.h"

namespace fg {

struct ReferenceSettings {
    double epsilon = 0.05;         // hit when d < epsilon * pixel half-diagonal cone at t
    int max_steps = 2000;
    double step_scale = 1.0;       // the pack's 1 / Lipschitz bound
    double step_fraction = 1.0;    // the pack's step_fraction: in step_scale, divided out of the hit test
};

struct ReferenceDepth {
    std::uint32_t width = 0, height = 0;
    std::vector<double> depth;     // distance along the ray, or -1 for a miss
    std::vector<int> steps;
};

double reference_trace(const CpuEvaluator& scene, const SceneSettings& s, const glm::dvec3& origin,
                       const glm::dvec3& dir, double cone_tan, const ReferenceSettings& r, int* steps = nullptr);
ReferenceDepth reference_depth(const CpuEvaluator& scene, const SceneSettings& s, const View& view,
                               double pixel_half_diagonal, const ReferenceSettings& r);

}  // namespace fg
