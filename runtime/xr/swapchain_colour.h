#pragma once
// Which colour swapchain format fgplay asks the OpenXR runtime for, and what its texels mean.
//
// The OpenXR specification treats every swapchain format except an sRGB one as linear, and the
// compositor encodes linear values for the display itself. The frame graph's final image holds
// display-encoded (sRGB) 8-bit values, the bytes fgplay writes to PNG. So an sRGB swapchain takes
// those bytes as they are (exact, and what the PNG and the desktop window show); a linear one must
// receive the decoded values, and at 8 bits that bands in the dark tones (the specification says
// to avoid 8-bit linear colour), so it is the last choice. docs/runtime.md, "The colour pipeline".
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::xr {

// In fgplay's order of preference: 8-bit sRGB (RGBA, then BGRA), then linear formats with enough
// precision for the decoded values (16-bit float, 16-bit and 10-bit UNORM), then 8-bit linear.
const std::vector<VkFormat>& colour_swapchain_preference();

bool is_srgb_format(VkFormat format);
// 8-bit linear: the runtime offered nothing better, and dark tones band.
bool is_8bit_linear_format(VkFormat format);
const char* colour_format_name(VkFormat format);

// The first format of the preference that the runtime offers and that `writable` accepts (fgplay
// writes swapchain images with copies and blits); none: nullopt.
std::optional<VkFormat> choose_colour_swapchain_format(const std::vector<std::int64_t>& offered,
                                                       const std::function<bool(VkFormat)>& writable);

}  // namespace fg::xr
