#include "vk/memory_type.h"

#include <bit>

#include <fmt/format.h>

#include "vk/vulkan_error.h"

namespace fg::vk {

namespace {

constexpr VkMemoryPropertyFlags kDeviceLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kHostVisible = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
constexpr VkMemoryPropertyFlags kHostCoherent = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kHostCached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

}  // namespace

const char* memory_kind_name(MemoryKind kind) {
    switch (kind) {
        case MemoryKind::DeviceLocal: return "device-local";
        case MemoryKind::HostVisible: return "host-visible";
        case MemoryKind::Readback: return "readback";
    }
    return "unknown";
}

std::vector<MemoryRequest> memory_preferences(MemoryKind kind) {
    switch (kind) {
        case MemoryKind::DeviceLocal:
            // Host-visible device memory (resizable BAR) is scarce; leave it to those who map.
            return {{kDeviceLocal, kHostVisible}};
        case MemoryKind::HostVisible:
            return {{kHostVisible | kHostCoherent, 0}};
        case MemoryKind::Readback:
            // Uncached CPU reads are many times slower, so cached wins over coherent; coherent
            // only saves an invalidate call.
            return {{kHostVisible | kHostCached | kHostCoherent, 0},
                    {kHostVisible | kHostCached, 0},
                    {kHostVisible | kHostCoherent, 0},
                    {kHostVisible, 0}};
    }
    return {};
}

std::optional<std::uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& properties,
                                              std::uint32_t type_bits, const MemoryRequest& request) {
    std::optional<std::uint32_t> best;
    int best_avoided = 0;
    for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
        if (!(type_bits & (1u << i))) continue;
        const VkMemoryPropertyFlags flags = properties.memoryTypes[i].propertyFlags;
        if ((flags & request.required) != request.required) continue;
        const int avoided = std::popcount(flags & request.avoided);
        if (!best || avoided < best_avoided) {
            best = i;
            best_avoided = avoided;
        }
    }
    return best;
}

std::uint32_t select_memory_type(const VkPhysicalDeviceMemoryProperties& properties, std::uint32_t type_bits,
                                 MemoryKind kind) {
    for (const MemoryRequest& request : memory_preferences(kind))
        if (auto index = find_memory_type(properties, type_bits, request)) return *index;
    throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY,
                      fmt::format("no {} memory type among the allowed types 0x{:x}", memory_kind_name(kind),
                                  type_bits));
}

}  // namespace fg::vk
