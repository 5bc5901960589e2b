// fgplay's response to each OpenXR session state.
#include <gtest/gtest.h>

#include "xr/session_lifecycle.h"

namespace fg::xr {
namespace {

TEST(SessionLifecycle, ReadyBeginsStoppingEndsExitingLeaves) {
    SessionLifecycle s;
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_IDLE), SessionAction::None);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_READY), SessionAction::Begin);
    EXPECT_TRUE(s.running());
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_SYNCHRONIZED), SessionAction::None);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_VISIBLE), SessionAction::None);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_FOCUSED), SessionAction::None);
    EXPECT_TRUE(s.focused());
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_STOPPING), SessionAction::End);
    EXPECT_FALSE(s.running());
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_IDLE), SessionAction::None);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_EXITING), SessionAction::Exit);
    EXPECT_EQ(s.history().size(), 8u);
}

TEST(SessionLifecycle, ASessionIsBegunOnceAndEndedOnce) {
    SessionLifecycle s;
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_READY), SessionAction::Begin);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_READY), SessionAction::None);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_STOPPING), SessionAction::End);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_STOPPING), SessionAction::None);
    // The runtime may make the session ready again (the user put the headset back on).
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_READY), SessionAction::Begin);
}

TEST(SessionLifecycle, LossPendingAndInstanceLossAreLosses) {
    SessionLifecycle s;
    s.on_state(XR_SESSION_STATE_READY);
    EXPECT_EQ(s.on_state(XR_SESSION_STATE_LOSS_PENDING), SessionAction::Lost);
    EXPECT_TRUE(s.lost());
    SessionLifecycle t;
    EXPECT_EQ(t.on_instance_loss(), SessionAction::Lost);
}

}  // namespace
}  // namespace fg::xr
