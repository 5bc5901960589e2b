#pragma once
// What fgplay does as the OpenXR session moves through its states: begin when READY, render
// while SYNCHRONIZED/VISIBLE/FOCUSED, end when STOPPING, leave when EXITING or LOSS_PENDING.
// Kept apart from the OpenXR calls so the rules read in one place and are tested on their own.
#include <string>
#include <vector>

#include <openxr/openxr.h>

namespace fg::xr {

enum class SessionAction { None, Begin, End, Exit, Lost };

class SessionLifecycle {
public:
    SessionAction on_state(XrSessionState state);
    SessionAction on_instance_loss() { lost_ = true; return SessionAction::Lost; }

    bool running() const { return running_; }      // between xrBeginSession and xrEndSession
    bool focused() const { return state_ == XR_SESSION_STATE_FOCUSED; }
    bool lost() const { return lost_; }
    XrSessionState state() const { return state_; }
    const std::vector<std::string>& history() const { return history_; }   // state names in order

private:
    XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
    bool running_ = false, lost_ = false;
    std::vector<std::string> history_;
};

const char* session_state_name(XrSessionState state);

}  // namespace fg::xr
