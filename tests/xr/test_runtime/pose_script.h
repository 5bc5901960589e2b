#pragma once
// Scripted head motion and session events for the test runtime.
//   FG_XR_TEST_POSES   JSON file: {"ipd": 0.064, "keys": [{"t": 0, "position": [x,y,z], "yaw_deg": 0,
//                      "pitch_deg": 0}, ...]} in the LOCAL space (metres), linearly interpolated and
//                      held after the last key. Default: a slow step forward while looking around.
//   FG_XR_TEST_EVENTS  comma list: "stop@N" (the user quits from the headset after frame N),
//                      "loss@N" (the session is lost after frame N).
//   FG_XR_TEST_SIZE    recommended per-eye size WxH (default 96x96).
//   FG_XR_TEST_PERIODS the display period: "MS:FRAMES,...,MS" (e.g. "0.01:25,1000": an impossible
//                      budget for 25 frames, then a generous one). Default 11.1 ms (90 Hz).
#include <string>
#include <vector>

#define XR_NO_PROTOTYPES
#include <openxr/openxr.h>

namespace fgxrt {

struct PoseKey {
    double t = 0.0;
    double position[3] = {0.0, 0.0, 0.0};
    double yaw_deg = 0.0, pitch_deg = 0.0;
};

class PoseScript {
public:
    PoseScript();   // reads FG_XR_TEST_POSES, or the default motion
    XrPosef head(double t) const;
    XrPosef eye(double t, int eye) const;   // 0 left, 1 right
    XrFovf fov(int eye) const;              // asymmetric, mirrored between the eyes, as in headsets
    const std::string& error() const { return error_; }

private:
    std::vector<PoseKey> keys_;
    double ipd_ = 0.064;
    std::string error_;
};

struct EventScript {
    EventScript();   // reads FG_XR_TEST_EVENTS and FG_XR_TEST_PERIODS
    int stop_at = -1, loss_at = -1;
    std::vector<std::pair<double, int>> periods;   // (ms, frames); the last holds for ever
    XrDuration period_ns(int frame) const;
};

}  // namespace fgxrt
