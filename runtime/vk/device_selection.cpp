#include "vk/device_selection.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include <fmt/format.h>

#include "vk/vulkan_error.h"

namespace fg::vk {

namespace {

constexpr std::uint32_t kRequiredApi = VK_API_VERSION_1_3;

std::string lowercase(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

bool all_digits(std::string_view text) {
    return !text.empty() &&
           std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::string device_list(std::span<const DeviceCandidate> candidates, bool require_timestamps) {
    std::string out;
    for (const DeviceCandidate& c : candidates) {
        out += "\n  " + describe(c);
        const std::string why = unsuitability(c, require_timestamps);
        if (!why.empty()) out += " (unusable: " + why + ")";
    }
    return out;
}

// Best-ranked suitable device among `picks`; ties go to the earlier one so the order the driver
// enumerates in stays the tie-breaker.
std::optional<std::size_t> best_of(std::span<const DeviceCandidate> candidates,
                                   const std::vector<std::size_t>& picks, bool require_timestamps) {
    std::optional<std::size_t> best;
    for (std::size_t i : picks) {
        if (!unsuitability(candidates[i], require_timestamps).empty()) continue;
        if (!best || device_type_rank(candidates[i].type) > device_type_rank(candidates[*best].type))
            best = i;
    }
    return best;
}

}  // namespace

std::optional<std::uint32_t> choose_compute_family(std::span<const VkQueueFamilyProperties> families) {
    std::optional<std::uint32_t> any_compute;
    for (std::uint32_t i = 0; i < families.size(); ++i) {
        const VkQueueFamilyProperties& family = families[i];
        if (!(family.queueFlags & VK_QUEUE_COMPUTE_BIT) || family.queueCount == 0) continue;
        if (family.timestampValidBits > 0) return i;
        if (!any_compute) any_compute = i;
    }
    return any_compute;
}

int device_type_rank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
        default: return 0;
    }
}

const char* device_type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

std::string unsuitability(const DeviceCandidate& candidate, bool require_timestamps) {
    if (candidate.api_version < kRequiredApi)
        return fmt::format("supports Vulkan {}.{}, needs 1.3", VK_API_VERSION_MAJOR(candidate.api_version),
                           VK_API_VERSION_MINOR(candidate.api_version));
    if (!candidate.compute_family) return "no compute queue";
    if (!candidate.synchronization2) return "no synchronization2";
    if (require_timestamps && !candidate.timestamps) return "no timestamp queries on its compute queue";
    return {};
}

std::string describe(const DeviceCandidate& candidate) {
    return fmt::format("{}: {} [{}, Vulkan {}.{}.{}]", candidate.index, candidate.name,
                       device_type_name(candidate.type), VK_API_VERSION_MAJOR(candidate.api_version),
                       VK_API_VERSION_MINOR(candidate.api_version), VK_API_VERSION_PATCH(candidate.api_version));
}

std::size_t choose_device(std::span<const DeviceCandidate> candidates, std::string_view choice,
                          bool require_timestamps) {
    if (candidates.empty())
        throw VulkanError(VK_ERROR_INCOMPATIBLE_DRIVER,
                          "no Vulkan device found: install mesa-vulkan-drivers for lavapipe");

    std::vector<std::size_t> picks;
    if (choice.empty()) {
        for (std::size_t i = 0; i < candidates.size(); ++i) picks.push_back(i);
    } else if (all_digits(choice)) {
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (std::to_string(candidates[i].index) == choice) picks.push_back(i);
    } else {
        const std::string needle = lowercase(choice);
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (lowercase(candidates[i].name).find(needle) != std::string::npos) picks.push_back(i);
    }

    if (picks.empty())
        throw VulkanError(VK_ERROR_INITIALIZATION_FAILED,
                          fmt::format("no Vulkan device matches '{}'; available devices:{}", choice,
                                      device_list(candidates, require_timestamps)));

    if (auto best = best_of(candidates, picks, require_timestamps)) return *best;

    if (choice.empty())
        throw VulkanError(VK_ERROR_INCOMPATIBLE_DRIVER,
                          fmt::format("no usable Vulkan device; available devices:{}",
                                      device_list(candidates, require_timestamps)));
    throw VulkanError(VK_ERROR_INITIALIZATION_FAILED,
                      fmt::format("Vulkan device '{}' cannot be used; available devices:{}", choice,
                                  device_list(candidates, require_timestamps)));
}

}  // namespace fg::vk
