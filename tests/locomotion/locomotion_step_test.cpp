// Locomotion's rules on their own, with hand-made probe answers.
#include <gtest/gtest.h>

#include "locomotion/locomotion.h"

namespace fg {
namespace {

ProbeResult one_sample(glm::dvec3 point, double distance) {
    ProbeResult r;
    r.samples.push_back({point, distance, {0.0, 1.0, 0.0}});
    return r;
}

TEST(Locomotion, WithoutAProbeAnswerTheHeadDoesNotMove) {
    Locomotion l({}, 1.0);
    glm::dvec3 p = l.step({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 1.0, 0.1);
    EXPECT_EQ(p, glm::dvec3(0.0));
}

TEST(Locomotion, SpeedIsProportionalToTheDistanceToTheNearestSurface) {
    LocomotionSettings s;
    s.speed_per_distance = 2.0;
    s.max_speed = 100.0;
    Locomotion far(s, 1.0), near(s, 1.0);
    far.on_probe(one_sample({0.0, 0.0, 0.0}, 1.0));
    near.on_probe(one_sample({0.0, 0.0, 0.0}, 0.1));
    double d_far = glm::length(far.step({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1.0, 0.01));
    double d_near = glm::length(near.step({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 1.0, 0.01));
    EXPECT_NEAR(d_far, 2.0 * 1.0 * 0.01, 1e-12);
    EXPECT_NEAR(d_near, 2.0 * 0.1 * 0.01, 1e-12);
}

TEST(Locomotion, SpeedScalesWithTheWorldScaleUpToItsLimit) {
    LocomotionSettings s;
    s.speed_per_distance = 1000.0;
    s.max_speed = 2.0;
    Locomotion small(s, 1.0), big(s, 10.0);
    small.on_probe(one_sample({0.0, 0.0, 0.0}, 100.0));
    big.on_probe(one_sample({0.0, 0.0, 0.0}, 100.0));
    EXPECT_NEAR(glm::length(small.step({}, {1.0, 0.0, 0.0}, 1.0, 0.1)), 0.2, 1e-12);
    EXPECT_NEAR(glm::length(big.step({}, {1.0, 0.0, 0.0}, 1.0, 0.1)), 2.0, 1e-12);
}

TEST(Locomotion, AStepNeverLeavesTheEmptyBallOfAnOldProbeLessTheHeadRadius) {
    LocomotionSettings s;
    s.speed_per_distance = 1e6;   // asks for far more than is safe
    s.max_speed = 1e6;
    s.head_radius = 0.01;
    Locomotion l(s, 1.0);
    // An old answer, taken half a unit behind the head: the ball reaches 0.5 - 0.01 ahead of it.
    l.on_probe(one_sample({0.0, 0.0, 0.5}, 1.0));
    glm::dvec3 p = l.step({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 1.0, 1.0);
    EXPECT_NEAR(p.z, -(1.0 - 0.01 - 0.5), 1e-12);
    // Once at the edge it stops.
    glm::dvec3 q = l.step(p, {0.0, 0.0, -1.0}, 1.0, 1.0);
    EXPECT_NEAR(glm::length(q - p), 0.0, 1e-9);
}

TEST(Locomotion, ProbesLookAheadAlongTheVelocity) {
    Locomotion l({}, 1.0, 0.1);
    auto pts = l.probe_points({1.0, 2.0, 3.0}, {0.0, 0.0, -10.0});
    ASSERT_EQ(pts.size(), 2u);
    EXPECT_EQ(pts[0], glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(pts[1], glm::dvec3(1.0, 2.0, 2.0));
}

}  // namespace
}  // namespace fg

#include "locomotion/comfort_vignette.h"

namespace fg {
namespace {

TEST(ComfortVignette, NoneAtRestGrowingWithSpeedAndTurningUpToTheScenesStrength) {
    EXPECT_EQ(comfort_vignette(0.0, 0.0, 0.8), 0.0);
    EXPECT_NEAR(comfort_vignette(1.0, 0.0, 0.8), 0.4, 1e-12);
    EXPECT_GT(comfort_vignette(1.0, 0.5, 0.8), comfort_vignette(1.0, 0.0, 0.8));
    EXPECT_EQ(comfort_vignette(100.0, 10.0, 0.8), 0.8);
    EXPECT_EQ(comfort_vignette(1.0, 1.0, 0.0), 0.0) << "a scene without a vignette gets none";
}

}  // namespace
}  // namespace fg
