#include "xr/swapchain_colour.h"

#include <algorithm>

namespace fg::xr {

const std::vector<VkFormat>& colour_swapchain_preference() {
    static const std::vector<VkFormat> preference = {
        VK_FORMAT_R8G8B8A8_SRGB,       VK_FORMAT_B8G8R8A8_SRGB,      VK_FORMAT_R16G16B16A16_SFLOAT,
        VK_FORMAT_R16G16B16A16_UNORM,  VK_FORMAT_A2B10G10R10_UNORM_PACK32, VK_FORMAT_R8G8B8A8_UNORM,
        VK_FORMAT_B8G8R8A8_UNORM};
    return preference;
}

bool is_srgb_format(VkFormat format) { return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB; }

bool is_8bit_linear_format(VkFormat format) {
    return format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_B8G8R8A8_UNORM;
}

const char* colour_format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_SRGB: return "R8G8B8A8_SRGB";
        case VK_FORMAT_B8G8R8A8_SRGB: return "B8G8R8A8_SRGB";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_R16G16B16A16_UNORM: return "R16G16B16A16_UNORM";
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32: return "A2B10G10R10_UNORM_PACK32";
        case VK_FORMAT_R8G8B8A8_UNORM: return "R8G8B8A8_UNORM";
        case VK_FORMAT_B8G8R8A8_UNORM: return "B8G8R8A8_UNORM";
        default: return "unknown format";
    }
}

std::optional<VkFormat> choose_colour_swapchain_format(const std::vector<std::int64_t>& offered,
                                                       const std::function<bool(VkFormat)>& writable) {
    for (VkFormat f : colour_swapchain_preference())
        if (std::find(offered.begin(), offered.end(), static_cast<std::int64_t>(f)) != offered.end() && writable(f)) return f;
    return std::nullopt;
}

}  // namespace fg::xr
