#include "xr/xr_instance.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "vk/log.h"
#include "xr/xr_error.h"

namespace fg::xr {

namespace {

std::vector<XrExtensionProperties> available_extensions() {
    std::uint32_t count = 0;
    XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
    if (XR_FAILED(r)) throw XrError(r, no_runtime_message(r));
    std::vector<XrExtensionProperties> out(count, {XR_TYPE_EXTENSION_PROPERTIES});
    check(xrEnumerateInstanceExtensionProperties(nullptr, count, &count, out.data()),
          "xrEnumerateInstanceExtensionProperties");
    out.resize(count);
    return out;
}

bool has(const std::vector<XrExtensionProperties>& list, const char* name) {
    return std::any_of(list.begin(), list.end(),
                       [&](const XrExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

XRAPI_ATTR XrBool32 XRAPI_CALL on_message(XrDebugUtilsMessageSeverityFlagsEXT severity,
                                          XrDebugUtilsMessageTypeFlagsEXT, const XrDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
    auto* log = static_cast<XrMessageLog*>(user);
    std::string text = fmt::format("{}: {}", data->functionName ? data->functionName : "", data->message ? data->message : "");
    if (severity & XR_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        ++log->errors;
        vk::logger().error("OpenXR: {}", text);
    } else {
        ++log->warnings;
        vk::logger().warn("OpenXR: {}", text);
    }
    if (log->messages.size() < 100) log->messages.push_back(text);
    return XR_FALSE;
}

}  // namespace

std::string no_runtime_message(XrResult result) {
    const char* json = std::getenv("XR_RUNTIME_JSON");
    return fmt::format(
        "no OpenXR runtime is available ({}). fgplay xr needs an OpenXR runtime with XR_KHR_vulkan_enable2 "
        "for a headset: install one (Monado: monado-service from Debian 13 or later, or built from source as "
        "bench/monado/build.sh does; SteamVR on other systems) or point XR_RUNTIME_JSON at a runtime manifest{}. "
        "Without a headset, play the pack in a window with `fgplay view PACK`.",
        result_name(result), json ? fmt::format(" (XR_RUNTIME_JSON is '{}')", json) : "");
}

OpenXrInstance::OpenXrInstance() {
    const auto available = available_extensions();
    if (!has(available, XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME))
        throw XrError(XR_ERROR_EXTENSION_NOT_PRESENT,
                      fmt::format("the OpenXR runtime lacks {}: fgplay renders with Vulkan and needs it",
                                  XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME));
    std::vector<const char*> extensions = {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME};
    visibility_mask_ = has(available, XR_KHR_VISIBILITY_MASK_EXTENSION_NAME);
    if (visibility_mask_) extensions.push_back(XR_KHR_VISIBILITY_MASK_EXTENSION_NAME);
    refresh_rate_ = has(available, XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME);
    if (refresh_rate_) extensions.push_back(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME);
    depth_layer_ = has(available, XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    if (depth_layer_) extensions.push_back(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    const bool debug_utils = has(available, XR_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debug_utils) extensions.push_back(XR_EXT_DEBUG_UTILS_EXTENSION_NAME);

    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strncpy(info.applicationInfo.applicationName, "fgplay", XR_MAX_APPLICATION_NAME_SIZE - 1);
    std::strncpy(info.applicationInfo.engineName, "Fractograph", XR_MAX_ENGINE_NAME_SIZE - 1);
    info.applicationInfo.applicationVersion = 1;
    info.applicationInfo.engineVersion = 1;
    info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.enabledExtensionNames = extensions.data();
    XrResult created = xrCreateInstance(&info, &instance_);
    if (created == XR_ERROR_RUNTIME_UNAVAILABLE || created == XR_ERROR_RUNTIME_FAILURE)
        throw XrError(created, no_runtime_message(created));
    check(created, "xrCreateInstance");

    if (debug_utils) {
        XrDebugUtilsMessengerCreateInfoEXT m{XR_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        m.messageSeverities = XR_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | XR_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        m.messageTypes = XR_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | XR_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                         XR_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT | XR_DEBUG_UTILS_MESSAGE_TYPE_CONFORMANCE_BIT_EXT;
        m.userCallback = on_message;
        m.userData = log_.get();
        auto create = function<PFN_xrCreateDebugUtilsMessengerEXT>("xrCreateDebugUtilsMessengerEXT");
        check(create(instance_, &m, &messenger_), "xrCreateDebugUtilsMessengerEXT");
    }

    XrInstanceProperties props{XR_TYPE_INSTANCE_PROPERTIES};
    check(xrGetInstanceProperties(instance_, &props), "xrGetInstanceProperties");
    runtime_name_ = props.runtimeName;

    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    XrResult got = xrGetSystem(instance_, &system_info, &system_);
    if (got == XR_ERROR_FORM_FACTOR_UNAVAILABLE)
        throw XrError(got, fmt::format("the OpenXR runtime '{}' sees no headset (XR_ERROR_FORM_FACTOR_UNAVAILABLE): "
                                       "connect and switch on the headset, or use `fgplay view PACK`",
                                       runtime_name_));
    check(got, "xrGetSystem");
    XrSystemProperties sp{XR_TYPE_SYSTEM_PROPERTIES};
    check(xrGetSystemProperties(instance_, system_, &sp), "xrGetSystemProperties");
    system_name_ = sp.systemName;
}

OpenXrInstance::~OpenXrInstance() {
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_xrDestroyDebugUtilsMessengerEXT>(lookup("xrDestroyDebugUtilsMessengerEXT"));
        destroy(messenger_);
    }
    if (instance_) xrDestroyInstance(instance_);
}

PFN_xrVoidFunction OpenXrInstance::lookup(const char* name) const {
    PFN_xrVoidFunction f = nullptr;
    check(xrGetInstanceProcAddr(instance_, name, &f), name);
    return f;
}

}  // namespace fg::xr
