#pragma once
// One eye's OpenXR swapchain: fgplay renders into its own storage image (the frame graph's
// final.<eye>) and blits it into the acquired swapchain image, scaling when the render
// resolution differs from the swapchain's.
#include <cstdint>
#include <vector>

#include "vk/context.h"
#include "vk/image.h"
#include "xr/xr_instance.h"

namespace fg::xr {

// The swapchain format fgplay picks from the runtime's list: 8-bit RGBA, UNORM first because the
// frame graph's final image already holds display values.
std::int64_t choose_swapchain_format(const std::vector<std::int64_t>& offered);

// A single-image, single-layer Vulkan swapchain of `usage` (colour or depth) and its images.
XrSwapchain create_vulkan_swapchain(XrSession session, XrSwapchainUsageFlags usage, std::int64_t format, std::uint32_t width,
                                    std::uint32_t height, std::vector<VkImage>& images, const char* what);

class EyeSwapchain {
public:
    EyeSwapchain(XrSession session, std::int64_t format, std::uint32_t width, std::uint32_t height);
    ~EyeSwapchain();
    EyeSwapchain(const EyeSwapchain&) = delete;
    EyeSwapchain& operator=(const EyeSwapchain&) = delete;

    // Acquire, wait, blit `source` (written by compute, left in GENERAL) and release.
    void present(const vk::Context& ctx, vk::StorageImage& source);

    XrSwapchain handle() const { return swapchain_; }
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

private:
    XrSwapchain swapchain_ = XR_NULL_HANDLE;
    std::vector<VkImage> images_;
    std::uint32_t width_ = 0, height_ = 0;
};

}  // namespace fg::xr
