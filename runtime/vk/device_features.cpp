#include "vk/device_features.h"

namespace fg::vk {

EnabledFeatures supported_features(VkPhysicalDevice physical) {
    VkPhysicalDeviceMaintenance4Features maintenance4{};
    maintenance4.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES;
    VkPhysicalDeviceHostQueryResetFeatures host_query_reset{};
    host_query_reset.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES;
    host_query_reset.pNext = &maintenance4;
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.pNext = &host_query_reset;
    vkGetPhysicalDeviceFeatures2(physical, &features);

    EnabledFeatures s;
    s.host_query_reset = host_query_reset.hostQueryReset == VK_TRUE;
    s.shader_float64 = features.features.shaderFloat64 == VK_TRUE;
    s.shader_int64 = features.features.shaderInt64 == VK_TRUE;
    s.maintenance4 = maintenance4.maintenance4 == VK_TRUE;
    return s;
}

DeviceFeatureChain::DeviceFeatureChain(const EnabledFeatures& enabled) {
    // Everything not named here stays off, so a shader that relies on an unrequested feature is
    // caught by validation on the development machine, not on a user's GPU.
    core_.shaderFloat64 = enabled.shader_float64 ? VK_TRUE : VK_FALSE;
    core_.shaderInt64 = enabled.shader_int64 ? VK_TRUE : VK_FALSE;

    host_query_reset_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES;
    host_query_reset_.hostQueryReset = enabled.host_query_reset ? VK_TRUE : VK_FALSE;
    host_query_reset_.pNext = &synchronization2_;
    synchronization2_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES;
    synchronization2_.synchronization2 = VK_TRUE;   // required: every barrier and submit uses it
    synchronization2_.pNext = &maintenance4_;
    maintenance4_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES;
    maintenance4_.maintenance4 = enabled.maintenance4 ? VK_TRUE : VK_FALSE;
}

}  // namespace fg::vk
