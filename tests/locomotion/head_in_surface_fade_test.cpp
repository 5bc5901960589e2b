// A head walked or leant into the surface sees black: the fade reads the probes' guaranteed
// clearance at the head.
#include <gtest/gtest.h>

#include "locomotion/head_in_surface_fade.h"

using namespace fg;

namespace {
ProbeSample probe(glm::dvec3 p, double d) {
    ProbeSample s;
    s.point = p;
    s.distance = d;
    return s;
}
constexpr double kRadius = 0.05;
}  // namespace

TEST(HeadInSurfaceFade, stays_bright_before_the_first_answer_and_while_the_head_is_surely_clear) {
    EXPECT_EQ(head_in_surface_brightness({}, glm::dvec3(0.0), kRadius), 1.0);
    // Flight stops a whole head radius from the surface: no fade there.
    EXPECT_EQ(head_in_surface_brightness({probe({0, 0, 0}, kRadius)}, glm::dvec3(0.0), kRadius), 1.0);
    // A near probe that guarantees the head clear outweighs a far one that guarantees nothing.
    EXPECT_EQ(head_in_surface_brightness({probe({1, 0, 0}, 0.0), probe({0, 0, 0.01}, 0.5)}, glm::dvec3(0.0), kRadius), 1.0);
}

TEST(HeadInSurfaceFade, fades_linearly_to_black_at_the_surface_and_inside) {
    EXPECT_NEAR(head_in_surface_brightness({probe({0, 0, 0}, 0.25 * kRadius)}, glm::dvec3(0.0), kRadius), 0.5, 1e-12);
    EXPECT_EQ(head_in_surface_brightness({probe({0, 0, 0}, 0.0)}, glm::dvec3(0.0), kRadius), 0.0);
    EXPECT_EQ(head_in_surface_brightness({probe({0, 0, 0}, -0.3)}, glm::dvec3(0.0), kRadius), 0.0);
    // An older answer 1 cm behind the head guarantees 1 cm less.
    EXPECT_NEAR(head_in_surface_brightness({probe({0, 0, 0.01}, 0.0325)}, glm::dvec3(0.0), kRadius), 0.9, 1e-12);
    // Moved past what any answer covers: nothing is guaranteed, so black.
    EXPECT_EQ(head_in_surface_brightness({probe({0, 0, 0.5}, 0.1)}, glm::dvec3(0.0), kRadius), 0.0);
}
