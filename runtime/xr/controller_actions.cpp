#include "xr/controller_actions.h"

#include <cstring>

#include <fmt/format.h>

#include "xr/xr_error.h"

namespace fg::xr {

namespace {

struct Binding {
    XrAction ControllerActions::*action;
    const char* path;
};

void copy_name(char* out, std::size_t size, const char* text) {
    std::strncpy(out, text, size - 1);
    out[size - 1] = '\0';
}

}  // namespace

ControllerActions::ControllerActions(XrInstance instance, XrSession session) : instance_(instance), session_(session) {
    hands_[0] = path("/user/hand/left");
    hands_[1] = path("/user/hand/right");

    XrActionSetCreateInfo si{XR_TYPE_ACTION_SET_CREATE_INFO};
    copy_name(si.actionSetName, sizeof si.actionSetName, "locomotion");
    copy_name(si.localizedActionSetName, sizeof si.localizedActionSetName, "Locomotion");
    check(xrCreateActionSet(instance_, &si, &set_), "xrCreateActionSet");

    auto make = [&](XrAction& out, const char* name, const char* localized, XrActionType type, bool per_hand) {
        XrActionCreateInfo ai{XR_TYPE_ACTION_CREATE_INFO};
        copy_name(ai.actionName, sizeof ai.actionName, name);
        copy_name(ai.localizedActionName, sizeof ai.localizedActionName, localized);
        ai.actionType = type;
        if (per_hand) {
            ai.countSubactionPaths = 2;
            ai.subactionPaths = hands_;
        }
        check(xrCreateAction(set_, &ai, &out), "xrCreateAction");
    };
    make(fly_, "fly", "Fly", XR_ACTION_TYPE_FLOAT_INPUT, false);
    make(aim_, "aim", "Aim", XR_ACTION_TYPE_POSE_INPUT, true);
    make(turn_, "turn", "Snap turn", XR_ACTION_TYPE_VECTOR2F_INPUT, false);
    make(scale_, "scale", "World scale", XR_ACTION_TYPE_VECTOR2F_INPUT, false);

    const std::vector<std::pair<const char*, std::vector<Binding>>> profiles = {
        {"/interaction_profiles/khr/simple_controller",
         {{&ControllerActions::fly_, "/user/hand/right/input/select/click"},
          {&ControllerActions::aim_, "/user/hand/left/input/aim/pose"},
          {&ControllerActions::aim_, "/user/hand/right/input/aim/pose"}}},
        {"/interaction_profiles/oculus/touch_controller",
         {{&ControllerActions::fly_, "/user/hand/right/input/trigger/value"},
          {&ControllerActions::aim_, "/user/hand/left/input/aim/pose"},
          {&ControllerActions::aim_, "/user/hand/right/input/aim/pose"},
          {&ControllerActions::turn_, "/user/hand/right/input/thumbstick"},
          {&ControllerActions::scale_, "/user/hand/left/input/thumbstick"}}},
        {"/interaction_profiles/valve/index_controller",
         {{&ControllerActions::fly_, "/user/hand/right/input/trigger/value"},
          {&ControllerActions::aim_, "/user/hand/left/input/aim/pose"},
          {&ControllerActions::aim_, "/user/hand/right/input/aim/pose"},
          {&ControllerActions::turn_, "/user/hand/right/input/thumbstick"},
          {&ControllerActions::scale_, "/user/hand/left/input/thumbstick"}}},
    };
    for (const auto& [profile, bindings] : profiles) {
        std::vector<XrActionSuggestedBinding> suggested;
        for (const auto& b : bindings) suggested.push_back({this->*b.action, path(b.path)});
        XrInteractionProfileSuggestedBinding sb{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        sb.interactionProfile = path(profile);
        sb.countSuggestedBindings = static_cast<std::uint32_t>(suggested.size());
        sb.suggestedBindings = suggested.data();
        // A runtime may not know a profile (XR_ERROR_PATH_UNSUPPORTED): the others still count.
        XrResult r = xrSuggestInteractionProfileBindings(instance_, &sb);
        if (XR_SUCCEEDED(r)) accepted_.emplace_back(profile);
        else if (r != XR_ERROR_PATH_UNSUPPORTED) check(r, "xrSuggestInteractionProfileBindings");
    }

    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &set_;
    check(xrAttachSessionActionSets(session_, &attach), "xrAttachSessionActionSets");

    XrActionSpaceCreateInfo space{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    space.action = aim_;
    space.subactionPath = hands_[1];
    space.poseInActionSpace.orientation.w = 1.0f;
    check(xrCreateActionSpace(session_, &space, &aim_space_), "xrCreateActionSpace");
}

ControllerActions::~ControllerActions() {
    if (aim_space_) xrDestroySpace(aim_space_);
    // Destroying the set destroys its actions.
    if (set_) xrDestroyActionSet(set_);
}

XrPath ControllerActions::path(const char* text) const {
    XrPath p = XR_NULL_PATH;
    check(xrStringToPath(instance_, text, &p), "xrStringToPath");
    return p;
}

float ControllerActions::read_float(XrAction action) const {
    XrActionStateGetInfo gi{XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = action;
    XrActionStateFloat state{XR_TYPE_ACTION_STATE_FLOAT};
    check(xrGetActionStateFloat(session_, &gi, &state), "xrGetActionStateFloat");
    return state.isActive ? state.currentState : 0.0f;
}

glm::dvec2 ControllerActions::read_vector(XrAction action) const {
    XrActionStateGetInfo gi{XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = action;
    XrActionStateVector2f state{XR_TYPE_ACTION_STATE_VECTOR2F};
    check(xrGetActionStateVector2f(session_, &gi, &state), "xrGetActionStateVector2f");
    return state.isActive ? glm::dvec2(state.currentState.x, state.currentState.y) : glm::dvec2(0.0);
}

ControllerState ControllerActions::sync(XrSpace base, XrTime time) {
    ControllerState out;
    XrActiveActionSet active{set_, XR_NULL_PATH};
    XrActionsSyncInfo si{XR_TYPE_ACTIONS_SYNC_INFO};
    si.countActiveActionSets = 1;
    si.activeActionSets = &active;
    // XR_SESSION_NOT_FOCUSED (a success code): no input this frame.
    if (check(xrSyncActions(session_, &si), "xrSyncActions") != XR_SUCCESS) return out;
    out.focused = true;
    out.fly = read_float(fly_);
    out.turn = read_vector(turn_);
    out.scale = read_vector(scale_);

    XrActionStateGetInfo gi{XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = aim_;
    gi.subactionPath = hands_[1];
    XrActionStatePose pose{XR_TYPE_ACTION_STATE_POSE};
    check(xrGetActionStatePose(session_, &gi, &pose), "xrGetActionStatePose");
    if (!pose.isActive) return out;
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    check(xrLocateSpace(aim_space_, base, time, &location), "xrLocateSpace");
    const XrSpaceLocationFlags needed = XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_POSITION_VALID_BIT;
    if ((location.locationFlags & needed) != needed) return out;
    out.aim_valid = true;
    const XrPosef& p = location.pose;
    out.aim_position = {p.position.x, p.position.y, p.position.z};
    out.aim_orientation = glm::normalize(glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z));
    return out;
}

std::string ControllerActions::current_profiles() const {
    std::string out;
    const char* names[2] = {"left", "right"};
    for (int hand = 1; hand >= 0; --hand) {
        XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
        check(xrGetCurrentInteractionProfile(session_, hands_[hand], &state), "xrGetCurrentInteractionProfile");
        std::string profile = "none";
        if (state.interactionProfile != XR_NULL_PATH) {
            char buffer[XR_MAX_PATH_LENGTH];
            std::uint32_t length = 0;
            check(xrPathToString(instance_, state.interactionProfile, sizeof buffer, &length, buffer), "xrPathToString");
            profile = buffer;
        }
        out += fmt::format("{}{} {}", out.empty() ? "" : ", ", names[hand], profile);
    }
    return out;
}

}  // namespace fg::xr
