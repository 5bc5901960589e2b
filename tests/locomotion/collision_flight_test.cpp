// Collisions with the real GPU probe on lavapipe, checked with the CPU twin of the scene: the
// probe agrees with the twin, and flights straight into the Mandelbulb at high speed, with probe
// answers that arrive two frames late, get close but never put the head inside the surface.
#include <deque>

#include "locomotion/collision_probe.h"
#include "locomotion/locomotion.h"
#include "runtime_test_support.h"

namespace fg {
namespace {

class CollisionFlight : public test::RuntimeTest {
protected:
    static void SetUpTestSuite() {
        pack_ = std::make_unique<Pack>(test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json")));
        twin_ = test::cpu_scene(*pack_);
    }
    static void TearDownTestSuite() {
        twin_.reset();
        pack_.reset();
    }
    static std::unique_ptr<Pack> pack_;
    static std::unique_ptr<test::CpuScene> twin_;
};
std::unique_ptr<Pack> CollisionFlight::pack_;
std::unique_ptr<test::CpuScene> CollisionFlight::twin_;

TEST_F(CollisionFlight, TheGpuProbeAgreesWithTheCpuTwin) {
    CollisionProbe probe(test::shared_context(), *pack_);
    std::vector<glm::dvec3> points = {{0.0, 0.0, 2.5}, {1.5, 0.3, 0.0}, {0.0, -1.2, 0.2}, {0.4, 0.4, 0.9}};
    auto result = probe.wait(probe.submit(points));
    ASSERT_TRUE(result);
    ASSERT_EQ(result->samples.size(), points.size());
    for (const auto& s : result->samples) {
        double cpu = twin_->evaluator->distance(s.point);
        EXPECT_NEAR(s.distance, cpu, 1e-3 + 1e-3 * std::abs(cpu)) << "at " << s.point.x << "," << s.point.y << "," << s.point.z;
        glm::dvec3 n = twin_->evaluator->normal(s.point, 1e-4);
        EXPECT_GT(glm::dot(glm::normalize(n), s.normal), 0.99);
    }
}

TEST_F(CollisionFlight, FlightsStraightIntoTheFractalAtHighSpeedNeverEnterIt) {
    CollisionProbe probe(test::shared_context(), *pack_);
    LocomotionSettings settings;
    settings.max_speed = 1000.0;          // no limit worth the name
    settings.head_radius = 0.002;
    const double dt = 1.0 / 90.0;
    const glm::dvec3 starts[] = {{0.0, 0.0, 3.0}, {3.0, 0.0, 0.0}, {0.0, 3.0, 0.0}, {-2.0, -2.0, 1.0}, {1.7, 1.1, -2.2}};
    // At 90 Hz: 0.44 of the free distance per frame, and 4.4 times it (only the probes' empty
    // balls stop that one).
    for (double per_distance : {40.0, 400.0})
    for (const auto& start : starts) {
        settings.speed_per_distance = per_distance;
        Locomotion loco(settings, 1.0);
        glm::dvec3 head = start;
        const glm::dvec3 dir = glm::normalize(-start);   // at the centre of the bulb
        std::deque<std::uint64_t> in_flight;
        double closest = 1e9;
        for (int frame = 0; frame < 150; ++frame) {
            // Answers are read two frames after they were asked for.
            if (in_flight.size() >= 2) {
                auto answer = probe.wait(in_flight.front());
                in_flight.pop_front();
                ASSERT_TRUE(answer);
                loco.on_probe(*answer);
            }
            head = loco.step(head, dir, 1.0, dt);
            in_flight.push_back(probe.submit(loco.probe_points(head, loco.velocity())));
            ASSERT_NE(in_flight.back(), 0u) << "no free probe slot";
            double d = twin_->evaluator->distance(head);
            closest = std::min(closest, d);
            ASSERT_GT(d, 0.0) << "the head entered the fractal at frame " << frame << " flying from " << start.x << ","
                              << start.y << "," << start.z;
        }
        for (auto t : in_flight) probe.wait(t);
        // It did not stop timidly far away: the flight reached the surface's neighbourhood.
        EXPECT_LT(closest, 0.02) << "from " << start.x << "," << start.y << "," << start.z;
    }
}

}  // namespace
}  // namespace fg
