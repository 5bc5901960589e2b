#pragma once
// The test runtime's objects behind the OpenXR handles, and the state that its report covers.
// One instance at a time is enough for fgplay.
#include <cstdint>
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#define XR_NO_PROTOTYPES
#define XR_USE_GRAPHICS_API_VULKAN
#include <vulkan/vulkan.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "frame_inspector.h"
#include "input_script.h"
#include "pose_script.h"
#include "runtime_report.h"

namespace fgxrt {

inline constexpr XrSystemId kSystemId = 1;
inline constexpr XrTime kPeriodNs = 11'111'111;   // 90 Hz

struct Swapchain;
struct ActionSet;

struct Action {
    ActionSet* set = nullptr;
    std::string name, localized;
    XrActionType type = XR_ACTION_TYPE_FLOAT_INPUT;
    std::vector<XrPath> subactions;
    // As of the last xrSyncActions: each bound component's value, and the combined state.
    std::vector<std::pair<XrPath, ComponentValue>> bound;
    bool active = false, changed = false;
    float x = 0.0f, y = 0.0f;
    XrTime last_change = 0;
};

struct ActionSet {
    std::string name, localized;
    std::uint32_t priority = 0;
    bool attached = false;
    std::vector<std::unique_ptr<Action>> actions;
};

struct Session {
    VkInstance vk_instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    std::uint32_t queue_family = 0, queue_index = 0;
    XrSessionState state = XR_SESSION_STATE_UNKNOWN;
    bool running = false, exit_requested = false, lost = false;
    XrTime begin_time = 0, next_display_time = 0, waited_display_time = 0;
    bool frame_waited = false, frame_begun = false;
    std::chrono::steady_clock::time_point begun{};   // the last xrBeginFrame
    std::vector<std::unique_ptr<Swapchain>> swapchains;
    std::unique_ptr<FrameInspector> inspector;
    // Input: the attached action sets, the interaction profile in use, the last sync's time.
    bool attached = false;
    std::vector<ActionSet*> attached_sets;
    XrPath profile = XR_NULL_PATH;
    XrTime synced_time = 0;
    bool synced_focused = false;
};

struct Swapchain {
    Session* session = nullptr;
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t width = 0, height = 0;
    std::vector<VkImage> images;
    std::vector<VkDeviceMemory> memory;
    std::uint32_t next = 0;
    std::int32_t acquired = -1, waited = -1, last_released = -1;
};

struct Space {
    Session* session = nullptr;
    XrReferenceSpaceType type = XR_REFERENCE_SPACE_TYPE_LOCAL;
    XrPosef pose{};
    Action* action = nullptr;                 // an action space: this action's pose
    XrPath subaction = XR_NULL_PATH;
};

struct Instance {
    bool vulkan2 = false, visibility_mask = false, depth_layer = false, refresh_rate = false;
    // FG_XR_TEST_STRETCH=1: as Monado, the predicted display period stretches to whole display
    // periods that cover the application's own frame interval (wall clock).
    bool stretch = false;
    // FG_XR_TEST_FIRST_PERIOD_MS: as Monado, the first xrWaitFrame predicts this placeholder period
    // whatever the display's is.
    double first_period_ms = 0.0;
    std::chrono::steady_clock::time_point last_wait{};
    bool requirements_queried = false;
    std::deque<XrEventDataBuffer> events;
    std::vector<std::unique_ptr<Session>> sessions;
    std::vector<std::unique_ptr<Space>> spaces;
    PoseScript poses;
    InputScript input;
    std::vector<std::string> paths;           // XrPath n is paths[n - 1]
    std::vector<std::unique_ptr<ActionSet>> action_sets;
    std::map<XrPath, std::vector<std::pair<Action*, XrPath>>> suggested;   // profile -> (action, binding)
    EventScript script;
    RuntimeReport report;
    XrTime clock = 1'000'000'000;
    std::uint32_t recommended_width[2] = {96, 96}, recommended_height[2] = {96, 96};   // per eye
};

// The live instance (null when none), and handle lookups that return null for a stale handle.
Instance* instance(XrInstance handle);
Instance* live_instance();
Session* session(XrSession handle);
Swapchain* swapchain(XrSwapchain handle);
Space* space(XrSpace handle);
ActionSet* action_set(XrActionSet handle);
Action* action(XrAction handle);
// The path's string, or null for XR_NULL_PATH or a path never made.
const std::string* path_string(XrPath path);
XrPath intern_path(const std::string& text);
double session_seconds(const Session& s, XrTime t);
// Every action space of the session's pose actions, and reference spaces, located in `base`.
XrResult locate(Session& s, Space& space, Space& base, XrTime time, XrSpaceLocation* location);

void push_state(Session& s, XrSessionState state);

// The per-file function tables that the proc-address lookup searches.
struct NamedFunction {
    const char* name;
    PFN_xrVoidFunction function;
};
extern const std::vector<NamedFunction> kInstanceFunctions;
extern const std::vector<NamedFunction> kSessionFunctions;
extern const std::vector<NamedFunction> kActionFunctions;

}  // namespace fgxrt
