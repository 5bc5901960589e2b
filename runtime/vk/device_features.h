#pragma once
// The features fgplay enables on its VkDevice, as the create info's feature chain.
//
// Another API may create the device for us and add its own feature structs to the chain: an
// OpenXR runtime's xrCreateVulkanDeviceKHR (XR_KHR_vulkan_enable2) inserts, for instance,
// VkPhysicalDeviceTimelineSemaphoreFeatures for its compositor. The chain therefore names each
// feature through its own struct (VkPhysicalDeviceHostQueryResetFeatures, ...) and the core 1.0
// features through pEnabledFeatures, never through VkPhysicalDeviceVulkan1{1,2,3}Features or
// VkPhysicalDeviceFeatures2: those aggregates forbid the very structs such a runtime adds
// (VUID-VkDeviceCreateInfo-pNext-02829, -02830, -06532, -00373), so one of them in our chain would
// turn the runtime's legal addition into an invalid device.
#include <vulkan/vulkan.h>

namespace fg::vk {

struct EnabledFeatures {
    bool host_query_reset = false;
    bool shader_float64 = false;
    bool shader_int64 = false;
    bool maintenance4 = false;   // SPIR-V 1.6 (glslang's vulkan1.3 target) declares workgroup sizes with LocalSizeId
};

// What the physical device supports, read through the same individual structs.
EnabledFeatures supported_features(VkPhysicalDevice physical);

// Owns the structs the chain points into; pinned in memory once built.
class DeviceFeatureChain {
public:
    explicit DeviceFeatureChain(const EnabledFeatures& enabled);
    DeviceFeatureChain(const DeviceFeatureChain&) = delete;
    DeviceFeatureChain& operator=(const DeviceFeatureChain&) = delete;

    // For VkDeviceCreateInfo::pNext and ::pEnabledFeatures.
    const void* next() const { return &host_query_reset_; }
    const VkPhysicalDeviceFeatures* core() const { return &core_; }

private:
    VkPhysicalDeviceFeatures core_{};
    VkPhysicalDeviceHostQueryResetFeatures host_query_reset_{};
    VkPhysicalDeviceSynchronization2Features synchronization2_{};
    VkPhysicalDeviceMaintenance4Features maintenance4_{};
};

}  // namespace fg::vk
