#pragma once
// Controller input through OpenXR actions. One action set, "locomotion":
//   fly    float    right trigger (select on the simple controller): flight along the aim
//   aim    pose     both hands' aim poses; the right hand's as an action space
//   turn   vector2f right thumbstick: x snap-turns (snap_turn.h)
//   scale  vector2f left thumbstick: y changes the world scale (world_scale.h)
// with suggested bindings for khr/simple_controller, oculus/touch_controller and
// valve/index_controller. The runtime picks the profile for the controllers it has.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#define XR_USE_GRAPHICS_API_VULKAN
#include <vulkan/vulkan.h>
#include <openxr/openxr.h>

namespace fg::xr {

struct ControllerState {
    double fly = 0.0;                    // 0..1
    glm::dvec2 turn{0.0}, scale{0.0};    // -1..1
    bool aim_valid = false;              // the right hand's aim pose is tracked
    glm::dvec3 aim_position{0.0};        // in the base space, metres
    glm::dquat aim_orientation{1.0, 0.0, 0.0, 0.0};   // -z along the aim
    bool focused = false;                // false: the runtime gave no input (session not focused)
};

class ControllerActions {
public:
    // Creates the action set and actions, suggests the bindings, attaches the set and creates the
    // right hand's aim space. Throws XrError.
    ControllerActions(XrInstance instance, XrSession session);
    ~ControllerActions();
    ControllerActions(const ControllerActions&) = delete;
    ControllerActions& operator=(const ControllerActions&) = delete;

    // xrSyncActions, then every action's state; aim located in `base` at `time`.
    ControllerState sync(XrSpace base, XrTime time);
    // "right /interaction_profiles/oculus/touch_controller, left ..." (after a profile change).
    std::string current_profiles() const;
    // The profiles whose suggested bindings the runtime accepted.
    const std::vector<std::string>& accepted_profiles() const { return accepted_; }

private:
    XrPath path(const char* text) const;
    float read_float(XrAction action) const;
    glm::dvec2 read_vector(XrAction action) const;

    XrInstance instance_;
    XrSession session_;
    XrActionSet set_ = XR_NULL_HANDLE;
    XrAction fly_ = XR_NULL_HANDLE, aim_ = XR_NULL_HANDLE, turn_ = XR_NULL_HANDLE, scale_ = XR_NULL_HANDLE;
    XrSpace aim_space_ = XR_NULL_HANDLE;
    XrPath hands_[2] = {XR_NULL_PATH, XR_NULL_PATH};   // left, right
    std::vector<std::string> accepted_;
};

}  // namespace fg::xr
