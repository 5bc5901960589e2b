// World scale: it follows the stick smoothly (exponentially, in log space), scales about the head,
// and stays inside the scene's bounds: a float floor for the eye separation, and the clearance the
// probes guarantee for growing.
#include <gtest/gtest.h>

#include <cmath>

#include "locomotion/play_space.h"
#include "locomotion/world_scale.h"

namespace fg {
namespace {

constexpr double kFrame = 1.0 / 90.0;
constexpr double kIpd = 0.064, kHead = 0.05;

TEST(WorldScale, it_approaches_its_target_exponentially_without_jumps) {
    WorldScale scale(1.0);
    double previous = 1.0, largest_step = 0.0;
    for (int f = 0; f < 90; ++f) {   // one second of full stick down
        double s = scale.update(-1.0, kFrame, {0.0, 0.0, 0.0}, kIpd, kHead, 10.0);
        EXPECT_LT(s, previous) << "monotone at frame " << f;
        largest_step = std::max(largest_step, std::abs(std::log(s / previous)));
        previous = s;
    }
    EXPECT_NEAR(scale.target(), std::exp(-1.0), 1e-9) << "full stick: e times per second";
    EXPECT_LT(largest_step, 0.02) << "no frame changes the scale by more than 2 %";
    const double gap = std::log(scale.current() / scale.target());
    for (int f = 0; f < 14; ++f) scale.update(0.0, kFrame, {0.0, 0.0, 0.0}, kIpd, kHead, 10.0);   // let go for 0.156 s
    EXPECT_NEAR(std::log(scale.current() / scale.target()), gap * std::exp(-14.0 * kFrame / 0.15), 1e-9)
        << "the remaining gap decays with the time constant";
}

TEST(WorldScale, the_stick_inside_the_dead_zone_leaves_it_alone) {
    WorldScale scale(3.0);
    for (int f = 0; f < 50; ++f) scale.update(0.1, kFrame, {0.0, 0.0, 0.0}, kIpd, kHead, 10.0);
    EXPECT_EQ(scale.current(), 3.0);
}

TEST(WorldScale, shrinking_stops_where_the_eyes_would_be_too_few_floats_apart) {
    WorldScaleSettings s;
    s.rate_per_s = 20.0;
    WorldScale scale(1.0, s);
    const glm::dvec3 far_out{1000.0, 0.0, 0.0};   // float spacing 6.1e-5 here
    for (int f = 0; f < 900; ++f) scale.update(-1.0, kFrame, far_out, kIpd, kHead, 10.0);
    const double floor = float_floor_scale(far_out, kIpd, s.float_spacings);
    EXPECT_NEAR(floor, 1024.0 * 6.103515625e-05 / kIpd, 1e-9);
    EXPECT_NEAR(scale.current(), floor, floor * 1e-6);
    EXPECT_STREQ(scale.limited_by(), "float floor");
    EXPECT_GE(kIpd * scale.current(), 1024.0 * 6.1e-5) << "the eyes stay 1024 float steps apart";
}

TEST(WorldScale, growing_stops_where_the_head_would_outgrow_the_guaranteed_empty_ball) {
    WorldScale scale(1.0);
    const double clearance = 0.2;   // scene units; the head radius is 0.05 m times the scale
    for (int f = 0; f < 900; ++f) scale.update(1.0, kFrame, {0.0, 0.0, 0.0}, kIpd, kHead, clearance);
    EXPECT_LE(kHead * scale.current(), clearance + 1e-12);
    EXPECT_NEAR(scale.current(), clearance / kHead, 1e-6);
    EXPECT_STREQ(scale.limited_by(), "clearance");
    WorldScale blind(1.0);
    for (int f = 0; f < 90; ++f) blind.update(1.0, kFrame, {0.0, 0.0, 0.0}, kIpd, kHead, 0.0);
    EXPECT_EQ(blind.current(), 1.0) << "no probe answer yet: no growing";
}

TEST(WorldScale, rescaling_the_play_space_keeps_the_head_in_place_and_scales_the_tracked_motion) {
    PlaySpace space(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}), 1.0);
    const glm::dvec3 tracked{0.3, 1.7, 0.2};
    const glm::dvec3 head = space.point(tracked);
    space.rescale_about(tracked, 0.25);
    EXPECT_NEAR(glm::length(space.point(tracked) - head), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(space.point(tracked + glm::dvec3(0.1, 0.0, 0.0)) - head), 0.025, 1e-12)
        << "10 cm of leaning moves the head 0.025 scene units at a quarter scale";
}

TEST(PlaySpace, wrapping_moves_the_head_by_whole_periods_into_the_central_cell) {
    PlaySpace space(look_at({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}), 1.0);
    const glm::dvec3 period{2.0, 3.0, 4.0};
    space.move({7.3, -11.0, 100.1});
    const glm::dvec3 tracked{0.1, 0.0, 0.0};
    const glm::dvec3 before = space.point(tracked);
    const glm::dvec3 shift = space.wrap(tracked, period);
    const glm::dvec3 after = space.point(tracked);
    for (int i = 0; i < 3; ++i) {
        EXPECT_GE(after[i], -period[i] / 2.0);
        EXPECT_LT(after[i], period[i] / 2.0);
        double cells = shift[i] / period[i];
        EXPECT_EQ(cells, std::round(cells)) << "whole periods on axis " << i;
    }
    EXPECT_NEAR(glm::length(before - shift - after), 0.0, 1e-12);
    EXPECT_EQ(space.wrap(tracked, period), glm::dvec3(0.0)) << "inside the cell: nothing to do";
    EXPECT_EQ(periodic_cell_shift({5.0, 5.0, 5.0}, {0.0, 2.0, -1.0}), glm::dvec3(0.0, 6.0, 0.0))
        << "axes without a period are left alone";
}

}  // namespace
}  // namespace fg
