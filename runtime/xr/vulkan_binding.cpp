#include "xr/vulkan_binding.h"

#include <fmt/format.h>

#include "vk/vulkan_error.h"
#include "xr/xr_error.h"

namespace fg::xr {

vk::ContextCreationHooks vulkan_creation_hooks(const OpenXrInstance& instance) {
    auto requirements_of = instance.function<PFN_xrGetVulkanGraphicsRequirements2KHR>("xrGetVulkanGraphicsRequirements2KHR");
    XrGraphicsRequirementsVulkan2KHR req{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR};
    check(requirements_of(instance.handle(), instance.system(), &req), "xrGetVulkanGraphicsRequirements2KHR");
    const XrVersion needed = XR_MAKE_VERSION(1, 3, 0);
    if (XR_MAKE_VERSION(XR_VERSION_MAJOR(req.minApiVersionSupported), XR_VERSION_MINOR(req.minApiVersionSupported), 0) > needed)
        throw XrError(XR_ERROR_RUNTIME_FAILURE,
                      fmt::format("the OpenXR runtime needs Vulkan {}.{} or newer; fgplay uses Vulkan 1.3",
                                  XR_VERSION_MAJOR(req.minApiVersionSupported), XR_VERSION_MINOR(req.minApiVersionSupported)));

    const XrInstance xr = instance.handle();
    const XrSystemId system = instance.system();
    vk::ContextCreationHooks hooks;
    hooks.create_instance = [&instance, xr, system](const VkInstanceCreateInfo& info, VkInstance& out) {
        auto create = instance.function<PFN_xrCreateVulkanInstanceKHR>("xrCreateVulkanInstanceKHR");
        XrVulkanInstanceCreateInfoKHR ci{XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR};
        ci.systemId = system;
        ci.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
        ci.vulkanCreateInfo = &info;
        VkResult vk_result = VK_SUCCESS;
        check(create(xr, &ci, &out, &vk_result), "xrCreateVulkanInstanceKHR");
        return vk_result;
    };
    hooks.physical_device = [&instance, xr, system](VkInstance vk_instance) {
        auto get = instance.function<PFN_xrGetVulkanGraphicsDevice2KHR>("xrGetVulkanGraphicsDevice2KHR");
        XrVulkanGraphicsDeviceGetInfoKHR gi{XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR};
        gi.systemId = system;
        gi.vulkanInstance = vk_instance;
        VkPhysicalDevice physical = VK_NULL_HANDLE;
        check(get(xr, &gi, &physical), "xrGetVulkanGraphicsDevice2KHR");
        return physical;
    };
    hooks.create_device = [&instance, xr, system](VkPhysicalDevice physical, const VkDeviceCreateInfo& info, VkDevice& out) {
        auto create = instance.function<PFN_xrCreateVulkanDeviceKHR>("xrCreateVulkanDeviceKHR");
        XrVulkanDeviceCreateInfoKHR ci{XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR};
        ci.systemId = system;
        ci.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
        ci.vulkanPhysicalDevice = physical;
        ci.vulkanCreateInfo = &info;
        VkResult vk_result = VK_SUCCESS;
        check(create(xr, &ci, &out, &vk_result), "xrCreateVulkanDeviceKHR");
        return vk_result;
    };
    return hooks;
}

XrGraphicsBindingVulkan2KHR graphics_binding(const vk::Context& ctx) {
    XrGraphicsBindingVulkan2KHR b{XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR};
    b.instance = ctx.instance();
    b.physicalDevice = ctx.physical();
    b.device = ctx.device();
    b.queueFamilyIndex = ctx.queue_family();
    b.queueIndex = 0;
    return b;
}

}  // namespace fg::xr
