#include "xr/session_lifecycle.h"

namespace fg::xr {

const char* session_state_name(XrSessionState state) {
    switch (state) {
        case XR_SESSION_STATE_IDLE: return "idle";
        case XR_SESSION_STATE_READY: return "ready";
        case XR_SESSION_STATE_SYNCHRONIZED: return "synchronized";
        case XR_SESSION_STATE_VISIBLE: return "visible";
        case XR_SESSION_STATE_FOCUSED: return "focused";
        case XR_SESSION_STATE_STOPPING: return "stopping";
        case XR_SESSION_STATE_LOSS_PENDING: return "loss_pending";
        case XR_SESSION_STATE_EXITING: return "exiting";
        default: return "unknown";
    }
}

SessionAction SessionLifecycle::on_state(XrSessionState state) {
    state_ = state;
    history_.emplace_back(session_state_name(state));
    switch (state) {
        case XR_SESSION_STATE_READY:
            if (running_) return SessionAction::None;
            running_ = true;
            return SessionAction::Begin;
        case XR_SESSION_STATE_STOPPING:
            if (!running_) return SessionAction::None;
            running_ = false;
            return SessionAction::End;
        case XR_SESSION_STATE_EXITING: return SessionAction::Exit;
        case XR_SESSION_STATE_LOSS_PENDING:
            lost_ = true;
            return SessionAction::Lost;
        default: return SessionAction::None;
    }
}

}  // namespace fg::xr
