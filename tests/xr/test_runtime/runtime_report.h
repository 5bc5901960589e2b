#pragma once
// What the test runtime saw, written as JSON to $FG_XR_TEST_REPORT when the instance is
// destroyed (and after each session ends), so a test can read it.
#include <string>
#include <vector>

namespace fgxrt {

struct RuntimeReport {
    int frames_waited = 0, frames_ended = 0, frames_with_layers = 0, frames_checked = 0, frames_good = 0;
    std::vector<std::string> failures;   // the first ones, each naming its frame
    std::vector<std::string> session_states;
    std::vector<std::string> swapchains;  // "R8G8B8A8_UNORM 96x96"
    int visibility_mask_calls = 0;
    int refresh_rate_calls = 0;              // xrGetDisplayRefreshRateFB
    double longest_period_ms = 0.0;          // the longest display period predicted
    std::vector<double> frame_ms;            // wall time from xrBeginFrame to xrEndFrame, per frame (and its
                                             // median and longest after the first 10, in the JSON)
    bool vulkan_instance_created = false, vulkan_device_created = false;
    std::vector<std::string> device_features_added;   // feature structs the runtime put into fgplay's device chain
    bool exit_requested = false, session_ended = false, session_destroyed = false, instance_destroyed = false;
    double mean_luma_left = 0.0, mean_luma_right = 0.0;   // of the last checked frame
    double eyes_differ_fraction = 0.0;                     // of the last checked frame
    std::vector<double> frame_luma;          // left eye's mean luma per ended frame; -1: no layer
    // Input: the profiles fgplay suggested bindings for, the one in use, xrSyncActions calls.
    std::vector<std::string> suggested_profiles;
    std::string interaction_profile = "none";
    int actions_synced = 0;
    // $FG_XR_TEST_REFERENCE: the last checked left eye against a PNG of the same size.
    bool reference_compared = false;
    double reference_differ_fraction = 1.0;   // pixels with a channel more than 2 levels off
    int reference_max_diff = 255;
    // $FG_XR_TEST_COLOUR_PNGS: every eye against the PNG fgplay wrote for its frame.
    struct Colour {
        int eyes_compared = 0;
        double worst = 0.0;
        std::string steps;
    } colour;
    int frames_with_depth = 0;                             // XR_KHR_composition_layer_depth on both views
    std::string depth_format;
    double sky_fraction[2] = {0.0, 0.0};                   // of the last frame's depth: pixels at maxDepth

    void fail(int frame, const std::string& what);
    void write() const;   // to $FG_XR_TEST_REPORT, if set
};

}  // namespace fgxrt
