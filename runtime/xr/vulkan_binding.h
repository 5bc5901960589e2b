#pragma once
// XR_KHR_vulkan_enable2: the OpenXR runtime creates fgplay's Vulkan instance and device (so that
// its compositor can add what it needs) and names the physical device wired to the headset.
#include "vk/context.h"
#include "xr/xr_instance.h"

namespace fg::xr {

// Checks the runtime's Vulkan version range (fgplay needs 1.3) and returns hooks for vk::Context.
vk::ContextCreationHooks vulkan_creation_hooks(const OpenXrInstance& instance);

XrGraphicsBindingVulkan2KHR graphics_binding(const vk::Context& ctx);

}  // namespace fg::xr
