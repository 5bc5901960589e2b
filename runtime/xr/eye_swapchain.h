#pragma once
// One eye's OpenXR colour swapchain: fgplay renders into its own storage image (the frame graph's
// final.<eye>, display-encoded sRGB bytes in an R8G8B8A8_UNORM image) and hands it over so that
// the headset shows what the PNG shows (swapchain_colour.h):
//   - into R8G8B8A8_SRGB of the same size, the bytes are copied as they are;
//   - otherwise they are copied into an R8G8B8A8_SRGB image of the render size, which says what
//     they are, and blitted from there: the blit decodes them, filters in linear light when the
//     sizes differ, and encodes for an sRGB swapchain or stores linear values in a linear one.
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "vk/context.h"
#include "vk/image.h"
#include "vk/transfer_image.h"
#include "xr/xr_instance.h"

namespace fg::xr {

// The colour format fgplay asks for (swapchain_colour.h), among those the runtime offers and
// the device can copy and blit into; throws XrError when there is none.
VkFormat choose_eye_swapchain_format(const vk::Context& ctx, const std::vector<std::int64_t>& offered);

// A single-image, single-layer Vulkan swapchain of `usage` (colour or depth) and its images.
XrSwapchain create_vulkan_swapchain(XrSession session, XrSwapchainUsageFlags usage, std::int64_t format, std::uint32_t width,
                                    std::uint32_t height, std::vector<VkImage>& images, const char* what);

class EyeSwapchain {
public:
    EyeSwapchain(XrSession session, VkFormat format, std::uint32_t width, std::uint32_t height);
    ~EyeSwapchain();
    EyeSwapchain(const EyeSwapchain&) = delete;
    EyeSwapchain& operator=(const EyeSwapchain&) = delete;

    // Acquire, wait, copy or blit `source` (written by compute, left in GENERAL) and release.
    void present(const vk::Context& ctx, vk::StorageImage& source);
    // The same copy or blit into an image of its own: what a later present of a source of this
    // size needs is made now (lavapipe compiles its blit at the first one), not in a frame.
    void prepare(const vk::Context& ctx, vk::StorageImage& source);

    XrSwapchain handle() const { return swapchain_; }
    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    VkFormat format() const { return format_; }

private:
    XrSwapchain swapchain_ = XR_NULL_HANDLE;
    std::vector<VkImage> images_;
    VkFormat format_;
    std::uint32_t width_ = 0, height_ = 0;
    // The final image's bytes labelled sRGB, for the blit: one per source size (a governor's levels).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::unique_ptr<vk::TransferImage>> encoded_;
    std::unique_ptr<vk::TransferImage> rehearsal_;   // prepare()'s target, the swapchain's size and format

    void copy(const vk::Context& ctx, vk::StorageImage& source, VkImage target, bool runtime_image);
};

}  // namespace fg::xr
