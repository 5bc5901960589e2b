// Collision probes in a deep zoom (graphs/hard/deep_zoom.json, precision "double"): each request is
// anchored at its first point, so the distances a few 1e-7 from the viewer keep their digits and
// the normals' taps 2e-9 apart stay apart.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "locomotion/collision_probe.h"
#include "runtime_test_support.h"

namespace fg {

// The fixture checks that no validation error was raised.
class CollisionDeepZoom : public test::RuntimeTest {};

TEST_F(CollisionDeepZoom, probes_of_a_double_pack_agree_with_the_cpu_twin_at_the_viewer_scale) {
    if (!test::shared_context().shader_float64_enabled()) GTEST_SKIP() << "no shaderFloat64";
    Pack pack = test::compile_pack(test::read_source_file("graphs/hard/deep_zoom.json"));
    ASSERT_EQ(pack.manifest.precision, "double");
    auto cpu = test::cpu_scene(pack);
    const SceneSettings& s = cpu->settings;
    const glm::dvec3 dir = glm::normalize(s.camera.target - s.camera.position);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < CollisionProbe::kMaxPoints; ++i)
        points.push_back(s.camera.position + dir * (4e-7 * static_cast<double>(i)));
    CollisionProbe probe(test::shared_context(), pack);
    auto ticket = probe.submit(points);
    ASSERT_NE(ticket, 0u);
    auto result = probe.wait(ticket);
    ASSERT_TRUE(result);
    ASSERT_EQ(result->samples.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& got = result->samples[i];
        const double want = cpu->evaluator->distance(points[i]);
        SCOPED_TRACE(fmt::format("point {}: GPU {:.6g}, CPU twin {:.6g}", i, got.distance, want));
        // 1 % of the world scale (the estimate's own floor near the surface, docs/stability.md).
        EXPECT_NEAR(got.distance, want, 1e-2 * s.world_scale);
        EXPECT_NEAR(glm::length(got.normal), 1.0, 1e-3);
        // The normal's taps are 1e-4 of the bounds' radius (2e-9) apart: float positions near
        // |p| = 0.9 (6e-8 apart) cannot hold them, offsets from the anchor can.
        const double h = 1e-4 * s.bounds_radius;
        glm::dvec3 n(0.0);
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 e(0.0);
            e[axis] = h;
            n[axis] = cpu->evaluator->distance(points[i] + e) - cpu->evaluator->distance(points[i] - e);
        }
        EXPECT_GT(glm::dot(got.normal, glm::normalize(n)), 0.95);
    }
}

}  // namespace fg
