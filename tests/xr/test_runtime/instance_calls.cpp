// The test runtime's instance-level calls: extensions, instance, system, views, events, and the
// XR_KHR_vulkan_enable2 calls that create fgplay's Vulkan instance and device.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include <openxr/openxr_reflection.h>

#include "runtime_objects.h"

namespace fgxrt {

namespace {

std::unique_ptr<Instance> g_instance;
VkInstance g_vk_instance = VK_NULL_HANDLE;   // the last one created through xrCreateVulkanInstanceKHR

struct ExtensionSpec {
    const char* name;
    std::uint32_t version;
};
constexpr ExtensionSpec kExtensions[] = {{XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME, 2}, {XR_KHR_VISIBILITY_MASK_EXTENSION_NAME, 2},
                                         {XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME, XR_KHR_composition_layer_depth_SPEC_VERSION},
                                         {XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME, XR_FB_display_refresh_rate_SPEC_VERSION}};

bool switched_on(const char* variable) {
    const char* value = std::getenv(variable);
    return value && *value == '1';
}

// FG_XR_TEST_NO_DEPTH_LAYER=1, FG_XR_TEST_NO_VISIBILITY_MASK=1, FG_XR_TEST_NO_REFRESH_RATE=1: a
// runtime without that extension.
std::vector<ExtensionSpec> offered_extensions() {
    std::vector<ExtensionSpec> out;
    for (const auto& e : kExtensions) {
        const std::string name = e.name;
        if (name == XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME && switched_on("FG_XR_TEST_NO_DEPTH_LAYER")) continue;
        if (name == XR_KHR_VISIBILITY_MASK_EXTENSION_NAME && switched_on("FG_XR_TEST_NO_VISIBILITY_MASK")) continue;
        if (name == XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME && switched_on("FG_XR_TEST_NO_REFRESH_RATE")) continue;
        out.push_back(e);
    }
    return out;
}

bool offers(const std::string& name) {
    const auto offered = offered_extensions();
    return std::any_of(offered.begin(), offered.end(), [&](const ExtensionSpec& e) { return name == e.name; });
}

bool chain_has(const void* next, VkStructureType type) {
    for (auto* s = static_cast<const VkBaseInStructure*>(next); s; s = s->pNext)
        if (s->sType == type) return true;
    return false;
}

template <typename T, typename Fill>
XrResult two_call(std::uint32_t capacity, std::uint32_t* count, T* out, std::size_t size, Fill fill) {
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = static_cast<std::uint32_t>(size);
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < size) return XR_ERROR_SIZE_INSUFFICIENT;
    for (std::size_t i = 0; i < size; ++i) fill(out[i], i);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateInstanceExtensionProperties(const char* layer, std::uint32_t capacity,
                                                                    std::uint32_t* count, XrExtensionProperties* props) {
    if (layer && *layer) return XR_ERROR_API_LAYER_NOT_PRESENT;
    const auto offered = offered_extensions();
    return two_call(capacity, count, props, offered.size(), [&](XrExtensionProperties& p, std::size_t i) {
        std::strncpy(p.extensionName, offered[i].name, XR_MAX_EXTENSION_NAME_SIZE - 1);
        p.extensionVersion = offered[i].version;
    });
}

XRAPI_ATTR XrResult XRAPI_CALL CreateInstance(const XrInstanceCreateInfo* info, XrInstance* out) {
    if (!info || !out) return XR_ERROR_VALIDATION_FAILURE;
    if (g_instance) return XR_ERROR_LIMIT_REACHED;
    auto inst = std::make_unique<Instance>();
    for (std::uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
        std::string name = info->enabledExtensionNames[i];
        if (name == XR_EXT_DEBUG_UTILS_EXTENSION_NAME) continue;   // the loader implements it
        if (!offers(name)) return XR_ERROR_EXTENSION_NOT_PRESENT;
        if (name == XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME) inst->vulkan2 = true;
        if (name == XR_KHR_VISIBILITY_MASK_EXTENSION_NAME) inst->visibility_mask = true;
        if (name == XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME) inst->depth_layer = true;
        if (name == XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME) inst->refresh_rate = true;
    }
    inst->stretch = switched_on("FG_XR_TEST_STRETCH");
    if (const char* first = std::getenv("FG_XR_TEST_FIRST_PERIOD_MS")) inst->first_period_ms = std::atof(first);
    // "WxH" for both eyes, or "WxH,WxH": a runtime may recommend a different size for each eye.
    if (const char* size = std::getenv("FG_XR_TEST_SIZE")) {
        unsigned w[2] = {0, 0}, h[2] = {0, 0};
        const int read = std::sscanf(size, "%ux%u,%ux%u", &w[0], &h[0], &w[1], &h[1]);
        if (read == 2) {
            w[1] = w[0];
            h[1] = h[0];
        }
        for (int eye = 0; eye < 2 && (read == 2 || read == 4); ++eye)
            if (w[eye] > 0 && h[eye] > 0 && w[eye] <= 4096 && h[eye] <= 4096) {
                inst->recommended_width[eye] = w[eye];
                inst->recommended_height[eye] = h[eye];
            }
    }
    if (!inst->poses.error().empty()) inst->report.fail(0, inst->poses.error());
    if (!inst->input.error().empty()) inst->report.fail(0, inst->input.error());
    g_instance = std::move(inst);
    *out = reinterpret_cast<XrInstance>(g_instance.get());
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL DestroyInstance(XrInstance handle) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    inst->report.instance_destroyed = true;
    inst->report.write();
    g_instance.reset();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetInstanceProperties(XrInstance handle, XrInstanceProperties* props) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    props->runtimeVersion = XR_MAKE_VERSION(0, 1, 0);
    std::strncpy(props->runtimeName, "Fractograph test runtime", XR_MAX_RUNTIME_NAME_SIZE - 1);
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL PollEvent(XrInstance handle, XrEventDataBuffer* event) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (inst->events.empty()) return XR_EVENT_UNAVAILABLE;
    *event = inst->events.front();
    inst->events.pop_front();
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL ResultToString(XrInstance, XrResult value, char buffer[XR_MAX_RESULT_STRING_SIZE]) {
    const char* name = nullptr;
    switch (value) {
#define FG_CASE(n, v) \
    case n: name = #n; break;
        XR_LIST_ENUM_XrResult(FG_CASE)
#undef FG_CASE
        default: break;
    }
    if (name) std::strncpy(buffer, name, XR_MAX_RESULT_STRING_SIZE - 1);
    else std::snprintf(buffer, XR_MAX_RESULT_STRING_SIZE, "XR_%s_%d", value < 0 ? "UNKNOWN_FAILURE" : "UNKNOWN_SUCCESS",
                       static_cast<int>(value));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL StructureTypeToString(XrInstance, XrStructureType value,
                                                     char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
    const char* name = nullptr;
    switch (value) {
#define FG_CASE(n, v) \
    case n: name = #n; break;
        XR_LIST_ENUM_XrStructureType(FG_CASE)
#undef FG_CASE
        default: break;
    }
    if (name) std::strncpy(buffer, name, XR_MAX_STRUCTURE_NAME_SIZE - 1);
    else std::snprintf(buffer, XR_MAX_STRUCTURE_NAME_SIZE, "XR_UNKNOWN_STRUCTURE_TYPE_%d", static_cast<int>(value));
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetSystem(XrInstance handle, const XrSystemGetInfo* info, XrSystemId* system) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    *system = kSystemId;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetSystemProperties(XrInstance handle, XrSystemId system, XrSystemProperties* props) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    props->systemId = kSystemId;
    props->vendorId = 0xF6;
    std::strncpy(props->systemName, "Fractograph scripted headset", XR_MAX_SYSTEM_NAME_SIZE - 1);
    props->graphicsProperties.maxSwapchainImageWidth = 4096;
    props->graphicsProperties.maxSwapchainImageHeight = 4096;
    props->graphicsProperties.maxLayerCount = XR_MIN_COMPOSITION_LAYERS_SUPPORTED;
    props->trackingProperties.orientationTracking = XR_TRUE;
    props->trackingProperties.positionTracking = XR_TRUE;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateViewConfigurations(XrInstance handle, XrSystemId system, std::uint32_t capacity,
                                                           std::uint32_t* count, XrViewConfigurationType* types) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return two_call(capacity, count, types, 1,
                    [](XrViewConfigurationType& t, std::size_t) { t = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO; });
}

XRAPI_ATTR XrResult XRAPI_CALL GetViewConfigurationProperties(XrInstance handle, XrSystemId system,
                                                              XrViewConfigurationType type,
                                                              XrViewConfigurationProperties* props) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    props->viewConfigurationType = type;
    props->fovMutable = XR_FALSE;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateViewConfigurationViews(XrInstance handle, XrSystemId system,
                                                               XrViewConfigurationType type, std::uint32_t capacity,
                                                               std::uint32_t* count, XrViewConfigurationView* views) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    return two_call(capacity, count, views, 2, [inst](XrViewConfigurationView& v, std::size_t eye) {
        v.recommendedImageRectWidth = inst->recommended_width[eye];
        v.recommendedImageRectHeight = inst->recommended_height[eye];
        v.maxImageRectWidth = 4096;
        v.maxImageRectHeight = 4096;
        v.recommendedSwapchainSampleCount = 1;
        v.maxSwapchainSampleCount = 1;
    });
}

XRAPI_ATTR XrResult XRAPI_CALL EnumerateEnvironmentBlendModes(XrInstance handle, XrSystemId system,
                                                              XrViewConfigurationType, std::uint32_t capacity,
                                                              std::uint32_t* count, XrEnvironmentBlendMode* modes) {
    if (!instance(handle)) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return two_call(capacity, count, modes, 1,
                    [](XrEnvironmentBlendMode& m, std::size_t) { m = XR_ENVIRONMENT_BLEND_MODE_OPAQUE; });
}

XRAPI_ATTR XrResult XRAPI_CALL GetVulkanGraphicsRequirements2KHR(XrInstance handle, XrSystemId system,
                                                                 XrGraphicsRequirementsVulkanKHR* req) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (!inst->vulkan2) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    req->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
    req->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
    inst->requirements_queried = true;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateVulkanInstanceKHR(XrInstance handle, const XrVulkanInstanceCreateInfoKHR* info,
                                                       VkInstance* out, VkResult* vk_result) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (!inst->vulkan2) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!inst->requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(info->pfnGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    if (!create) return XR_ERROR_RUNTIME_FAILURE;
    // A compositor would add the instance extensions it needs here; this one needs none.
    *vk_result = create(info->vulkanCreateInfo, info->vulkanAllocator, out);
    if (*vk_result == VK_SUCCESS) {
        g_vk_instance = *out;
        inst->report.vulkan_instance_created = true;
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL GetVulkanGraphicsDevice2KHR(XrInstance handle, const XrVulkanGraphicsDeviceGetInfoKHR* info,
                                                           VkPhysicalDevice* out) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (!inst->vulkan2) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!inst->requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    std::uint32_t count = 0;
    if (vkEnumeratePhysicalDevices(info->vulkanInstance, &count, nullptr) != VK_SUCCESS || count == 0)
        return XR_ERROR_RUNTIME_FAILURE;
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(info->vulkanInstance, &count, devices.data());
    // The "headset" is wired to the CPU device (lavapipe) where there is one, as in CI.
    *out = devices[0];
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) *out = d;
    }
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL CreateVulkanDeviceKHR(XrInstance handle, const XrVulkanDeviceCreateInfoKHR* info,
                                                     VkDevice* out, VkResult* vk_result) {
    Instance* inst = instance(handle);
    if (!inst) return XR_ERROR_HANDLE_INVALID;
    if (!inst->vulkan2) return XR_ERROR_FUNCTION_UNSUPPORTED;
    if (!inst->requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    if (!g_vk_instance) return XR_ERROR_RUNTIME_FAILURE;
    auto create = reinterpret_cast<PFN_vkCreateDevice>(info->pfnGetInstanceProcAddr(g_vk_instance, "vkCreateDevice"));
    if (!create) return XR_ERROR_RUNTIME_FAILURE;
    // As Monado does for its compositor: where the application's chain has no
    // VkPhysicalDeviceTimelineSemaphoreFeatures, one goes in front. Legal on its own, invalid next
    // to an application's VkPhysicalDeviceVulkan12Features (VUID-VkDeviceCreateInfo-pNext-02830).
    VkDeviceCreateInfo modified = *info->vulkanCreateInfo;
    VkPhysicalDeviceTimelineSemaphoreFeatures timeline{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES};
    if (!chain_has(modified.pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES)) {
        timeline.timelineSemaphore = VK_TRUE;
        timeline.pNext = const_cast<void*>(modified.pNext);
        modified.pNext = &timeline;
        inst->report.device_features_added.push_back("VkPhysicalDeviceTimelineSemaphoreFeatures");
    }
    *vk_result = create(info->vulkanPhysicalDevice, &modified, info->vulkanAllocator, out);
    if (*vk_result == VK_SUCCESS) inst->report.vulkan_device_created = true;
    return XR_SUCCESS;
}

#define FG_FN(name) {"xr" #name, reinterpret_cast<PFN_xrVoidFunction>(&name)}

}  // namespace

Instance* instance(XrInstance handle) {
    return g_instance && reinterpret_cast<Instance*>(handle) == g_instance.get() ? g_instance.get() : nullptr;
}

Instance* live_instance() { return g_instance.get(); }

void push_state(Session& s, XrSessionState state) {
    Instance* inst = g_instance.get();
    s.state = state;
    XrEventDataBuffer buffer{XR_TYPE_EVENT_DATA_BUFFER};
    auto& e = reinterpret_cast<XrEventDataSessionStateChanged&>(buffer);
    e.type = XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED;
    e.next = nullptr;
    e.session = reinterpret_cast<XrSession>(&s);
    e.state = state;
    e.time = inst->clock;
    inst->events.push_back(buffer);
    static const char* names[] = {"unknown", "idle", "ready", "synchronized", "visible", "focused", "stopping", "loss_pending", "exiting"};
    inst->report.session_states.emplace_back(state >= 0 && state <= 8 ? names[state] : "?");
}

const std::vector<NamedFunction> kInstanceFunctions = {
    FG_FN(EnumerateInstanceExtensionProperties),
    FG_FN(CreateInstance),
    FG_FN(DestroyInstance),
    FG_FN(GetInstanceProperties),
    FG_FN(PollEvent),
    FG_FN(ResultToString),
    FG_FN(StructureTypeToString),
    FG_FN(GetSystem),
    FG_FN(GetSystemProperties),
    FG_FN(EnumerateViewConfigurations),
    FG_FN(GetViewConfigurationProperties),
    FG_FN(EnumerateViewConfigurationViews),
    FG_FN(EnumerateEnvironmentBlendModes),
    FG_FN(GetVulkanGraphicsRequirements2KHR),
    FG_FN(CreateVulkanInstanceKHR),
    FG_FN(GetVulkanGraphicsDevice2KHR),
    FG_FN(CreateVulkanDeviceKHR),
};

}  // namespace fgxrt
