#pragma once
// Scripted controllers for the test runtime.
//   FG_XR_TEST_INPUT  JSON file: {"profile": "oculus/touch_controller", "keys": [{"t": 0,
//                     "right": {"trigger": 0.8, "thumbstick": [1, 0], "squeeze": 0, "select": true,
//                               "aim": {"position": [x,y,z], "yaw_deg": 0, "pitch_deg": 0}},
//                     "left": {...}}, ...]}
//                     Each key holds until the next one (a stick is pushed, not eased); a hand
//                     missing from a key keeps its previous state. Aim poses are in the LOCAL space
//                     (metres); without one the aim follows the head, 20 cm right, 30 cm down, 30 cm
//                     ahead. `profile` is the controller the "headset" has (default
//                     oculus/touch_controller; also khr/simple_controller, valve/index_controller).
#include <optional>
#include <string>
#include <vector>

#define XR_NO_PROTOTYPES
#include <openxr/openxr.h>

namespace fgxrt {

struct HandInput {
    double trigger = 0.0, squeeze = 0.0;
    double thumbstick[2] = {0.0, 0.0};
    std::optional<bool> select;              // default: trigger >= 0.5
    bool has_aim = false;
    double aim_position[3] = {0.0, 0.0, 0.0};
    double aim_yaw_deg = 0.0, aim_pitch_deg = 0.0;
};

struct InputKey {
    double t = 0.0;
    HandInput hands[2];                      // left, right
};

// What a binding path reads: a float (bool inputs as 0 or 1), a 2D vector or a pose.
struct ComponentValue {
    float x = 0.0f, y = 0.0f;
    bool is_vector = false;
};

class InputScript {
public:
    InputScript();   // reads FG_XR_TEST_INPUT
    const std::string& profile() const { return profile_; }   // "/interaction_profiles/..."
    const std::string& error() const { return error_; }
    bool scripted() const { return !keys_.empty(); }

    // The state of `component` ("/user/hand/right/input/thumbstick/x") at `t` seconds.
    ComponentValue value(const std::string& component, double t) const;
    // The hand's aim pose in LOCAL at `t`, given the head's pose then.
    XrPosef aim(int hand, double t, const XrPosef& head) const;

private:
    const HandInput& hand(int hand, double t) const;

    std::string profile_ = "/interaction_profiles/oculus/touch_controller";
    std::vector<InputKey> keys_;
    std::string error_;
};

}  // namespace fgxrt
