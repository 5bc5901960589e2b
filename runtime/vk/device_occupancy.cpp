#include "vk/device_occupancy.h"

#include "vk/extensions.h"

namespace fg::vk {

std::uint64_t resident_invocations(VkPhysicalDevice physical) {
    const auto extensions = device_extensions(physical);
    // A properties struct may only be chained when its extension is supported.
    VkPhysicalDeviceShaderSMBuiltinsPropertiesNV nv{};
    nv.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_SM_BUILTINS_PROPERTIES_NV;
    VkPhysicalDeviceShaderCorePropertiesAMD amd{};
    amd.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_CORE_PROPERTIES_AMD;
    VkPhysicalDeviceSubgroupProperties subgroup{};
    subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
    const bool has_nv = has_extension(extensions, VK_NV_SHADER_SM_BUILTINS_EXTENSION_NAME);
    const bool has_amd = has_extension(extensions, VK_AMD_SHADER_CORE_PROPERTIES_EXTENSION_NAME);
    if (!has_nv && !has_amd) return 0;
    if (has_nv) subgroup.pNext = &nv;
    else subgroup.pNext = &amd;
    VkPhysicalDeviceProperties2 properties{};
    properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical, &properties);
    if (has_nv) return std::uint64_t(nv.shaderSMCount) * nv.shaderWarpsPerSM * subgroup.subgroupSize;
    return std::uint64_t(amd.shaderEngineCount) * amd.shaderArraysPerEngineCount * amd.computeUnitsPerShaderArray *
           amd.simdPerComputeUnit * amd.wavefrontsPerSimd * amd.wavefrontSize;
}

}  // namespace fg::vk
