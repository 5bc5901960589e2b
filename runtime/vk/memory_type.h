#pragma once
// Choosing a memory type by what the memory is for, not by raw property flags.
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

enum class MemoryKind {
    DeviceLocal,  // fastest for the GPU; reached from the host only through staging copies
    HostVisible,  // host coherent and persistently mapped: uploads, uniforms, small results
    Readback,     // host visible, host cached where the device offers it: reading results back
};

const char* memory_kind_name(MemoryKind kind);

struct MemoryRequest {
    VkMemoryPropertyFlags required = 0;
    VkMemoryPropertyFlags avoided = 0;  // among fitting types, fewer of these is better
};

// What each kind asks for, best first; later entries are fallbacks.
std::vector<MemoryRequest> memory_preferences(MemoryKind kind);

// The allowed (by `type_bits`) memory type with every required flag and the fewest avoided
// ones; ties go to the lower index, as the spec orders types by preference. Empty when none fits.
std::optional<std::uint32_t> find_memory_type(const VkPhysicalDeviceMemoryProperties& properties,
                                              std::uint32_t type_bits, const MemoryRequest& request);

// The first of the kind's preferences that some allowed type meets; throws
// VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY) naming the kind when none does.
std::uint32_t select_memory_type(const VkPhysicalDeviceMemoryProperties& properties, std::uint32_t type_bits,
                                 MemoryKind kind);

}  // namespace fg::vk
