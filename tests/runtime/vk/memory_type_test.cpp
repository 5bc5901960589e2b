// Memory type choice against the memory layout of a typical discrete GPU.
#include <gtest/gtest.h>

#include "vk/memory_type.h"
#include "vk/vulkan_error.h"

namespace fg::vk {
namespace {

constexpr VkMemoryPropertyFlags kDevice = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kVisible = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
constexpr VkMemoryPropertyFlags kCoherent = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kCached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

VkPhysicalDeviceMemoryProperties memory_types(std::initializer_list<VkMemoryPropertyFlags> types) {
    VkPhysicalDeviceMemoryProperties props{};
    for (VkMemoryPropertyFlags flags : types) props.memoryTypes[props.memoryTypeCount++] = {flags, 0};
    props.memoryHeapCount = 1;
    return props;
}

// 0: VRAM, 1: resizable-BAR VRAM, 2: write-combined system memory, 3: cached system memory.
const VkPhysicalDeviceMemoryProperties kDiscrete =
    memory_types({kDevice, kDevice | kVisible | kCoherent, kVisible | kCoherent, kVisible | kCoherent | kCached});
constexpr std::uint32_t kAllTypes = 0xF;

TEST(MemoryType, DeviceLocalMemoryAvoidsTheScarceHostVisibleVram) {
    EXPECT_EQ(select_memory_type(kDiscrete, kAllTypes, MemoryKind::DeviceLocal), 0u);
    // With plain VRAM excluded by the resource, the BAR heap is still device local.
    EXPECT_EQ(select_memory_type(kDiscrete, 0xE, MemoryKind::DeviceLocal), 1u);
}

TEST(MemoryType, HostVisibleMemoryIsCoherent) {
    EXPECT_EQ(select_memory_type(kDiscrete, kAllTypes, MemoryKind::HostVisible), 1u);
    EXPECT_EQ(select_memory_type(kDiscrete, 0xC, MemoryKind::HostVisible), 2u);
}

TEST(MemoryType, ReadbackMemoryPrefersHostCached) {
    EXPECT_EQ(select_memory_type(kDiscrete, kAllTypes, MemoryKind::Readback), 3u);
    // Cached but not coherent still beats coherent but uncached.
    const auto props = memory_types({kVisible | kCoherent, kVisible | kCached});
    EXPECT_EQ(select_memory_type(props, 0x3, MemoryKind::Readback), 1u);
}

TEST(MemoryType, TheResourcesAllowedTypesAreRespected) {
    EXPECT_EQ(find_memory_type(kDiscrete, 0x1, {kVisible, 0}), std::nullopt);
    try {
        select_memory_type(kDiscrete, 0x1, MemoryKind::HostVisible);
        FAIL() << "no host-visible type is allowed, yet one was selected";
    } catch (const VulkanError& e) {
        EXPECT_NE(std::string(e.what()).find("no host-visible memory type"), std::string::npos) << e.what();
    }
}

TEST(MemoryType, OneMemoryTypeForEverythingServesEveryKind) {
    // lavapipe and many integrated GPUs.
    const auto unified = memory_types({kDevice | kVisible | kCoherent | kCached});
    EXPECT_EQ(select_memory_type(unified, 0x1, MemoryKind::DeviceLocal), 0u);
    EXPECT_EQ(select_memory_type(unified, 0x1, MemoryKind::HostVisible), 0u);
    EXPECT_EQ(select_memory_type(unified, 0x1, MemoryKind::Readback), 0u);
}

}  // namespace
}  // namespace fg::vk
