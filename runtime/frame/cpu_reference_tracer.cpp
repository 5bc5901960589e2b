#include "cpu_reference_tracer.h"

#include <cmath>

namespace fg {

double reference_trace(const CpuEvaluator& scene, const SceneSettings& s, const glm::dvec3& origin,
                       const glm::dvec3& dir, double cone_tan, const ReferenceSettings& r, int* steps) {
    glm::dvec3 oc = s.bounds_center - origin;
    double b = glm::dot(oc, dir);
    double h = b * b - (glm::dot(oc, oc) - s.bounds_radius * s.bounds_radius);
    if (steps) *steps = 0;
    if (h < 0.0) return -1.0;
    h = std::sqrt(h);
    double t = std::max(b - h, 0.0), far = std::min(b + h, s.max_distance);
    for (int i = 0; i < r.max_steps && t <= far; ++i) {
        double d = scene.distance(origin + dir * t) * r.step_scale;
        if (steps) ++*steps;
        if (d < r.epsilon * r.step_fraction * cone_tan * t) return t;
        t += d;
    }
    return t <= far ? t : -1.0;
}

ReferenceDepth reference_depth(const CpuEvaluator& scene, const SceneSettings& s, const View& view,
                               double pixel_half_diagonal, const ReferenceSettings& r) {
    ReferenceDepth out{view.width, view.height, {}, {}};
    out.depth.resize(static_cast<std::size_t>(view.width) * view.height);
    out.steps.resize(out.depth.size());
    double cone = std::tan(pixel_half_diagonal);
    for (std::uint32_t y = 0; y < view.height; ++y)
        for (std::uint32_t x = 0; x < view.width; ++x) {
            std::size_t i = static_cast<std::size_t>(y) * view.width + x;
            glm::dvec3 dir = view.ray((x + 0.5) / view.width, (y + 0.5) / view.height);
            out.depth[i] = reference_trace(scene, s, view.origin, dir, cone, r, &out.steps[i]);
        }
    return out;
}

}  // namespace fg
