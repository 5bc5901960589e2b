#include "runtime_report.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fgxrt {

void RuntimeReport::fail(int frame, const std::string& what) {
    if (failures.size() < 20) failures.push_back("frame " + std::to_string(frame) + ": " + what);
}

void RuntimeReport::write() const {
    const char* path = std::getenv("FG_XR_TEST_REPORT");
    if (!path || !*path) return;
    nlohmann::json j;
    j["runtime"] = "Fractograph test runtime";
    j["frames_waited"] = frames_waited;
    j["frames_ended"] = frames_ended;
    j["frames_with_layers"] = frames_with_layers;
    j["frames_checked"] = frames_checked;
    j["frames_good"] = frames_good;
    j["failures"] = failures;
    j["session_states"] = session_states;
    j["swapchains"] = swapchains;
    j["visibility_mask_calls"] = visibility_mask_calls;
    j["refresh_rate_calls"] = refresh_rate_calls;
    j["longest_period_ms"] = longest_period_ms;
    j["frame_ms"] = frame_ms;
    // A stall is a frame far longer than the run's usual one, after the first frames (pipelines).
    std::vector<double> later(frame_ms.begin() + std::min<std::size_t>(10, frame_ms.size()), frame_ms.end());
    std::vector<double> sorted = later;
    std::sort(sorted.begin(), sorted.end());
    // Whole microseconds: CMake's tests compare integers only.
    j["median_frame_us_after_10"] = sorted.empty() ? 0 : std::lround(1000.0 * sorted[sorted.size() / 2]);
    j["longest_frame_us_after_10"] = sorted.empty() ? 0 : std::lround(1000.0 * sorted.back());
    j["vulkan_instance_created_by_runtime"] = vulkan_instance_created;
    j["vulkan_device_created_by_runtime"] = vulkan_device_created;
    j["device_features_added_by_runtime"] = device_features_added;
    j["exit_requested"] = exit_requested;
    j["session_ended"] = session_ended;
    j["session_destroyed"] = session_destroyed;
    j["instance_destroyed"] = instance_destroyed;
    j["last_frame"] = {{"mean_luma_left", mean_luma_left}, {"mean_luma_right", mean_luma_right},
                       {"eyes_differ_fraction", eyes_differ_fraction}};
    j["frame_luma"] = frame_luma;
    j["suggested_profiles"] = suggested_profiles;
    j["interaction_profile"] = interaction_profile;
    j["actions_synced"] = actions_synced;
    if (reference_compared)
        j["reference"] = {{"differ_fraction", reference_differ_fraction}, {"max_diff", reference_max_diff}};
    j["colour"] = {{"eyes_compared", colour.eyes_compared}, {"worst", colour.worst}, {"steps", colour.steps}};
    j["depth_layer"] = {{"frames_with_depth", frames_with_depth},
                        {"format", depth_format},
                        {"sky_fraction_left", sky_fraction[0]},
                        {"sky_fraction_right", sky_fraction[1]}};
    std::ofstream(path) << j.dump(2) << "\n";
}

}  // namespace fgxrt
