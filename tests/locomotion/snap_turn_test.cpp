// Snap turns: edge-triggered, past a dead zone, faded to black and back, the yaw applied once at
// black, about the head.
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "locomotion/play_space.h"
#include "locomotion/snap_turn.h"

namespace fg {
namespace {

constexpr double kFrame = 1.0 / 90.0;

TEST(SnapTurn, a_push_fades_to_black_turns_ninety_degrees_once_at_black_and_fades_back) {
    SnapTurn snap;
    std::vector<double> brightness;
    double yaw = 0.0;
    int yaw_frame = -1;
    for (int f = 0; f < 40; ++f) {
        SnapTurnFrame out = snap.update(1.0, kFrame);   // held right the whole time
        brightness.push_back(out.brightness);
        if (out.yaw_rad != 0.0) {
            EXPECT_EQ(yaw_frame, -1) << "a held stick turns once";
            yaw_frame = f;
        }
        yaw += out.yaw_rad;
    }
    EXPECT_NEAR(yaw, -std::numbers::pi / 2.0, 1e-12) << "right turns the view right: negative about +y";
    ASSERT_GE(yaw_frame, 0);
    EXPECT_EQ(brightness[static_cast<std::size_t>(yaw_frame)], 0.0) << "the turn happens while the view is black";
    for (int f = 1; f <= yaw_frame; ++f) EXPECT_LT(brightness[f], brightness[f - 1]) << "fading out at frame " << f;
    for (int f = yaw_frame + 1; f < 40 && brightness[f - 1] < 1.0; ++f)
        EXPECT_GT(brightness[f], brightness[f - 1]) << "fading in at frame " << f;
    EXPECT_EQ(brightness.back(), 1.0);
    EXPECT_EQ(snap.turns(), 1);
    // 0.1 s out at 90 Hz: 9 or 10 frames to black.
    EXPECT_GE(yaw_frame, 8);
    EXPECT_LE(yaw_frame, 11);
}

TEST(SnapTurn, the_stick_must_return_inside_the_dead_zone_before_the_next_turn) {
    SnapTurn snap;
    auto run = [&](double x, int frames) {
        double yaw = 0.0;
        for (int f = 0; f < frames; ++f) yaw += snap.update(x, kFrame).yaw_rad;
        return yaw;
    };
    EXPECT_NE(run(1.0, 40), 0.0);
    EXPECT_EQ(run(0.5, 40), 0.0) << "0.5 is neither a push nor inside the 0.3 dead zone";
    EXPECT_EQ(run(1.0, 40), 0.0) << "not re-armed yet";
    EXPECT_EQ(run(0.1, 2), 0.0);
    EXPECT_NEAR(run(-1.0, 40), std::numbers::pi / 2.0, 1e-12) << "left turns left";
    EXPECT_EQ(snap.turns(), 2);
}

TEST(SnapTurn, small_stick_noise_never_turns_and_bad_input_is_ignored) {
    SnapTurn snap;
    for (int f = 0; f < 200; ++f) {
        SnapTurnFrame out = snap.update(0.69 * ((f % 2) ? 1.0 : -1.0), kFrame);
        EXPECT_EQ(out.yaw_rad, 0.0);
        EXPECT_EQ(out.brightness, 1.0);
    }
    SnapTurnFrame out = snap.update(std::nan(""), kFrame);
    EXPECT_EQ(out.brightness, 1.0);
}

TEST(PlaySpace, a_turn_about_the_head_keeps_the_head_where_it_is_and_turns_the_view) {
    HeadPose origin = look_at({1.0, 2.0, 3.0}, {0.0, 2.0, 0.0});
    PlaySpace space(origin, 2.5);
    const glm::dvec3 tracked{0.4, 1.6, -0.3};   // the head, away from the play space's origin
    const glm::dvec3 before = space.point(tracked);
    const glm::dvec3 forward_before = space.direction({0.0, 0.0, -1.0});
    space.turn_about(tracked, -std::numbers::pi / 2.0);
    EXPECT_NEAR(glm::length(space.point(tracked) - before), 0.0, 1e-12);
    const glm::dvec3 forward_after = space.direction({0.0, 0.0, -1.0});
    EXPECT_NEAR(glm::dot(forward_before, forward_after), 0.0, 1e-12) << "a quarter turn";
    EXPECT_NEAR(glm::dot(glm::cross(forward_before, forward_after), space.direction({0.0, 1.0, 0.0})), -1.0, 1e-12)
        << "to the right, about the play space's up";
    // Turning about the origin of the play space would have moved the head.
    PlaySpace about_origin(origin, 2.5);
    about_origin.turn_about({0.0, 0.0, 0.0}, -std::numbers::pi / 2.0);
    EXPECT_GT(glm::length(about_origin.point(tracked) - before), 0.5);
}

}  // namespace
}  // namespace fg
