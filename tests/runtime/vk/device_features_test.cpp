// The device's feature chain survives a creator that adds its own feature structs, as OpenXR
// runtimes do inside xrCreateVulkanDeviceKHR.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "vk/context.h"
#include "vk/device_features.h"
#include "vk_test_support.h"

namespace fg::vk {
namespace {

std::vector<VkStructureType> chain_types(const void* next) {
    std::vector<VkStructureType> types;
    for (auto* s = static_cast<const VkBaseInStructure*>(next); s; s = s->pNext) types.push_back(s->sType);
    return types;
}

TEST(DeviceFeatureChain, NamesEachFeatureInItsOwnStructAndNoAggregate) {
    EnabledFeatures wanted;
    wanted.host_query_reset = true;
    wanted.shader_float64 = true;
    DeviceFeatureChain chain(wanted);
    EXPECT_EQ(chain.core()->shaderFloat64, VK_TRUE);
    EXPECT_EQ(chain.core()->shaderInt64, VK_FALSE);
    for (VkStructureType t : chain_types(chain.next())) {
        EXPECT_NE(t, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
        EXPECT_NE(t, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
        EXPECT_NE(t, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
        EXPECT_NE(t, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    }
    EXPECT_EQ(chain_types(chain.next()).size(), 3u);
}

// What Monado's xrCreateVulkanDeviceKHR does: where the application's chain has no
// VkPhysicalDeviceTimelineSemaphoreFeatures, it puts one at the front for its compositor.
VkResult create_device_adding_timeline_semaphores(VkPhysicalDevice physical, const VkDeviceCreateInfo& info, VkDevice& out) {
    VkPhysicalDeviceTimelineSemaphoreFeatures timeline{};
    timeline.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES;
    timeline.timelineSemaphore = VK_TRUE;
    timeline.pNext = const_cast<void*>(info.pNext);
    VkDeviceCreateInfo modified = info;
    modified.pNext = &timeline;
    return vkCreateDevice(physical, &modified, nullptr, &out);
}

TEST(DeviceFeatureChain, ARuntimeAddingTimelineSemaphoreFeaturesLeavesTheDeviceValid) {
    ContextOptions options = test::validated_options();
    options.shader_float64 = true;
    options.hooks.create_device = &create_device_adding_timeline_semaphores;
    auto ctx = std::make_unique<Context>(options);
    ASSERT_TRUE(ctx->validation_enabled());
    auto log = ctx->validation_log();
    ctx.reset();
    EXPECT_EQ(log->errors(), 0u) << test::joined(log->messages());
}

}  // namespace
}  // namespace fg::vk
