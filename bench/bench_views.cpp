#include "bench_views.h"

#include <cmath>

#include "frame/cpu_reference_tracer.h"

namespace fg::bench {

std::vector<BenchView> make_bench_views(const CpuEvaluator& scene, const SceneSettings& s) {
    std::vector<BenchView> views;
    HeadPose start = look_at(s.camera.position, s.camera.target, s.camera.up);
    views.push_back({"afar", start, s.world_scale});

    // The first surface straight ahead of the scene camera.
    glm::dvec3 forward = glm::normalize(s.camera.target - s.camera.position);
    ReferenceSettings rs;
    rs.epsilon = 1e-4;
    double t = reference_trace(scene, s, s.camera.position, forward, 1e-3, rs);
    if (t < 0.0) t = glm::length(s.camera.target - s.camera.position);
    glm::dvec3 hit = s.camera.position + forward * t;
    glm::dvec3 n = scene.normal(hit, 1e-5);
    double R = s.bounds_radius;

    // Filled: close to the surface, looking at it, so every pixel sees fractal.
    glm::dvec3 filled = hit - forward * (0.25 * R);
    views.push_back({"filled", look_at(filled, hit, s.camera.up), s.world_scale});

    // Grazing: near the surface, looking along it, tilted 15 degrees into it.
    glm::dvec3 tangent = forward - n * glm::dot(forward, n);
    if (glm::length(tangent) < 1e-6) tangent = glm::cross(n, glm::dvec3(0.0, 1.0, 0.0));
    tangent = glm::normalize(tangent);
    glm::dvec3 along = glm::normalize(tangent * std::cos(glm::radians(15.0)) - n * std::sin(glm::radians(15.0)));
    glm::dvec3 grazing = hit + n * (0.05 * R) - along * (0.3 * R);
    views.push_back({"grazing", look_at(grazing, grazing + along, n), s.world_scale});

    // Deep zoom: a thousandth of the distance, and a thousandth of the viewer's size.
    glm::dvec3 deep = hit - forward * (0.25 * R * 1e-3);
    views.push_back({"deep_zoom", look_at(deep, hit, s.camera.up), s.world_scale * 1e-3});
    return views;
}

}  // namespace fg::bench
