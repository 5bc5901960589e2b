#pragma once
// How many shader invocations a device runs at once. Persistent lanes launch enough workgroups to
// fill it: a queue drained by fewer lanes than the device holds leaves most of a GPU idle.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace fg::vk {

// From the vendors' core counts (VK_NV_shader_sm_builtins: SMs x warps per SM x subgroup size;
// VK_AMD_shader_core_properties: wavefront slots); 0 when the device does not say, as core Vulkan
// does not.
std::uint64_t resident_invocations(VkPhysicalDevice physical);

}  // namespace fg::vk
