#pragma once
// Picking the physical device and its queue family, kept apart from the Context so the ranking
// rules can be tested on machines that have only one (CPU) device.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <vulkan/vulkan.h>

namespace fg::vk {

// What the selection needs to know about one physical device.
struct DeviceCandidate {
    std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::uint32_t api_version = 0;
    std::optional<std::uint32_t> compute_family;  // as chosen by choose_compute_family
    bool timestamps = false;                      // on that family, with a non-zero period
    bool synchronization2 = false;
};

// The first queue family with compute, preferring one that can write timestamps.
std::optional<std::uint32_t> choose_compute_family(std::span<const VkQueueFamilyProperties> families);

// Higher is preferred: discrete > integrated > virtual > cpu > other.
int device_type_rank(VkPhysicalDeviceType type);
const char* device_type_name(VkPhysicalDeviceType type);

// Why the device cannot run Fractograph, or an empty string when it can.
std::string unsuitability(const DeviceCandidate& candidate, bool require_timestamps);

// "1: llvmpipe (LLVM 15.0.6, 256 bits) [cpu, Vulkan 1.3.230]"
std::string describe(const DeviceCandidate& candidate);

// `choice` is empty (best suitable device), all digits (an index into the enumeration), or a
// case-insensitive substring of the device name. Returns a position in `candidates`; throws
// VulkanError with the list of available devices when nothing fits.
std::size_t choose_device(std::span<const DeviceCandidate> candidates, std::string_view choice,
                          bool require_timestamps);

}  // namespace fg::vk
