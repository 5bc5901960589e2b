// The frame-rate governor: down under pressure, back up with room, no flicker in between.
#include <gtest/gtest.h>

#include "frame/frame_governor.h"

namespace fg::xr {
namespace {

std::vector<GovernorLevel> ladder(int n) {
    std::vector<GovernorLevel> l(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) l[static_cast<std::size_t>(i)].render_scale = 1.0 - 0.1 * i;
    return l;
}

TEST(FrameGovernor, AnImpossibleBudgetDrivesTheSettingsToTheFloorAndSaysSo) {
    FrameGovernor g(ladder(4));
    bool said = false;
    for (int i = 0; i < 100; ++i) {
        g.observe(20.0, 11.1);
        said = said || g.message().find("at the floor") != std::string::npos;
    }
    EXPECT_TRUE(g.at_floor());
    EXPECT_TRUE(said);
}

TEST(FrameGovernor, AGenerousBudgetLetsTheSettingsClimbBack) {
    FrameGovernor g(ladder(4));
    for (int i = 0; i < 100; ++i) g.observe(20.0, 11.1);
    for (int i = 0; i < 200; ++i) g.observe(2.0, 11.1);
    EXPECT_EQ(g.level(), 0);
}

TEST(FrameGovernor, ATimeBetweenTheThresholdsChangesNothing) {
    // 80 % of the budget: not over it, not well under it. No flicker.
    FrameGovernor g(ladder(4));
    for (int i = 0; i < 30; ++i) g.observe(20.0, 11.1);
    int level = g.level();
    int changes = 0;
    for (int i = 0; i < 200; ++i) changes += g.observe(0.8 * 11.1, 11.1) ? 1 : 0;
    EXPECT_EQ(changes, 0);
    EXPECT_EQ(g.level(), level);
}

TEST(FrameGovernor, TwoRungsThatStraddleTheBudgetSettleInsteadOfSwitchingForEver) {
    // Level 1 costs 60 ms of a 50 ms budget, level 2 26 ms, under 60 % of it: a climb from 2 to 1
    // always falls back. The first climbs come quickly, later ones ever more rarely.
    FrameGovernor g(ladder(4));
    for (int i = 0; i < 20; ++i) g.observe(70.0, 50.0);   // down from 0 to where it fits
    int changes_late = 0, backoffs = 0;
    for (int frame = 0; frame < 600; ++frame) {
        const double ms = g.level() <= 1 ? 60.0 : 26.0;
        const bool changed = g.observe(ms, 50.0);
        if (frame >= 300) changes_late += changed ? 1 : 0;
        backoffs += g.message().find("climbing there again waits") != std::string::npos ? 1 : 0;
    }
    EXPECT_LE(changes_late, 6) << "at most 2 changes per 100 frames once settled";
    EXPECT_GE(backoffs, 3) << "each failed climb says so";
    EXPECT_GE(g.level(), 1);
}

TEST(FrameGovernor, OneSlowFrameDoesNotStepDown) {
    FrameGovernor g(ladder(4));
    for (int i = 0; i < 10; ++i) g.observe(5.0, 11.1);
    g.observe(40.0, 11.1);
    for (int i = 0; i < 10; ++i) g.observe(5.0, 11.1);
    EXPECT_EQ(g.level(), 0);
}

TEST(FrameGovernor, TheLadderKeepsKnobsInsideTheirRanges) {
    PackManifest m;
    ManifestSpecConstant eps;
    eps.name = "epsilon";
    eps.value = 0.5;
    eps.max = 1.0;
    m.spec_constants.push_back(eps);
    auto l = governor_ladder(m);
    ASSERT_GE(l.size(), 3u);
    EXPECT_TRUE(l[0].knobs.empty()) << "level 0 is the pack's own accuracy";
    for (const auto& level : l)
        if (level.knobs.count("epsilon")) EXPECT_LE(level.knobs.at("epsilon"), 1.0);
    EXPECT_LT(l.back().render_scale, 1.0);
}

}  // namespace
}  // namespace fg::xr
