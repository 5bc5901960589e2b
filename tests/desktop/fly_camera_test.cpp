// The preview's camera: looking around never rolls, and flying follows the view.
#include <gtest/gtest.h>

#include "desktop/fly_camera.h"

namespace fg::desktop {
namespace {

TEST(FlyCamera, StartsLookingWhereTheSceneCameraLooks) {
    FlyCamera c(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}));
    EXPECT_NEAR(c.forward().z, -1.0, 1e-9);
    FlyCamera d(look_at({0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}));
    EXPECT_NEAR(c.forward().y, 0.0, 1e-9);
    EXPECT_NEAR(d.forward().x, std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(d.forward().y, std::sqrt(0.5), 1e-9);
}

TEST(FlyCamera, FlyingForwardMovesAlongTheViewByTheDistance) {
    FlyCamera c(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}));
    c.fly(1.0, 0.0, 0.0, 0.5);
    EXPECT_NEAR(c.pose().position.z, 2.5, 1e-9);
    c.fly(0.0, 1.0, 0.0, 1.0);
    EXPECT_NEAR(c.pose().position.x, 1.0, 1e-9);
}

TEST(FlyCamera, LookingAroundKeepsTheHorizonLevelAndStopsShortOfThePoles) {
    FlyCamera c(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}));
    c.look(300.0, -100000.0);
    glm::dvec3 right = glm::mat3_cast(c.pose().orientation) * glm::dvec3(1.0, 0.0, 0.0);
    EXPECT_NEAR(right.y, 0.0, 1e-9) << "no roll";
    EXPECT_LT(c.forward().y, 1.0);
    EXPECT_GT(c.forward().y, 0.99);
}

}  // namespace
}  // namespace fg::desktop
