#pragma once
// The OpenXR instance and the head-mounted system: the extensions fgplay needs
// (XR_KHR_vulkan_enable2) and the ones it uses where present (XR_KHR_visibility_mask,
// XR_KHR_composition_layer_depth, XR_FB_display_refresh_rate, XR_EXT_debug_utils, through which
// the core validation layer's messages are counted).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#define XR_USE_GRAPHICS_API_VULKAN
#include <vulkan/vulkan.h>
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

namespace fg::xr {

// What the debug messenger saw: kept apart from the instance so that late messages still land.
struct XrMessageLog {
    std::size_t errors = 0, warnings = 0;
    std::vector<std::string> messages;
};

class OpenXrInstance {
public:
    // Throws XrError; with no runtime installed its message says what is missing and what to do.
    OpenXrInstance();
    ~OpenXrInstance();
    OpenXrInstance(const OpenXrInstance&) = delete;
    OpenXrInstance& operator=(const OpenXrInstance&) = delete;

    XrInstance handle() const { return instance_; }
    XrSystemId system() const { return system_; }
    const std::string& runtime_name() const { return runtime_name_; }
    const std::string& system_name() const { return system_name_; }
    bool has_visibility_mask() const { return visibility_mask_; }
    bool has_depth_layer() const { return depth_layer_; }   // XR_KHR_composition_layer_depth
    bool has_refresh_rate() const { return refresh_rate_; }  // XR_FB_display_refresh_rate
    const XrMessageLog& messages() const { return *log_; }

    // An extension function; throws when the runtime does not provide it.
    template <typename Pfn>
    Pfn function(const char* name) const {
        return reinterpret_cast<Pfn>(lookup(name));
    }

private:
    PFN_xrVoidFunction lookup(const char* name) const;

    XrInstance instance_ = XR_NULL_HANDLE;
    XrDebugUtilsMessengerEXT messenger_ = XR_NULL_HANDLE;
    XrSystemId system_ = XR_NULL_SYSTEM_ID;
    std::string runtime_name_, system_name_;
    bool visibility_mask_ = false;
    bool depth_layer_ = false;
    bool refresh_rate_ = false;
    std::unique_ptr<XrMessageLog> log_ = std::make_unique<XrMessageLog>();
};

// The text fgplay prints when no OpenXR runtime answers.
std::string no_runtime_message(XrResult result);

}  // namespace fg::xr
