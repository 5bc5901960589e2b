#include "xr/eye_swapchain.h"

#include <algorithm>
#include <fmt/format.h>

#include "vk/commands.h"
#include "xr/swapchain_colour.h"
#include "xr/xr_error.h"

namespace fg::xr {

VkFormat choose_eye_swapchain_format(const vk::Context& ctx, const std::vector<std::int64_t>& offered) {
    auto writable = [&](VkFormat f) {
        VkFormatProperties support{};
        vkGetPhysicalDeviceFormatProperties(ctx.physical(), f, &support);
        const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_TRANSFER_DST_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
        return (support.optimalTilingFeatures & needed) == needed;
    };
    if (auto chosen = choose_colour_swapchain_format(offered, writable)) {
        if (is_8bit_linear_format(*chosen))
            fmt::print("colour: the runtime offers no sRGB or deep swapchain format; {} holds linear values, so dark tones band\n",
                       colour_format_name(*chosen));
        return *chosen;
    }
    throw XrError(XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED,
                  "the OpenXR runtime offers no colour swapchain format fgplay can write (8-bit RGBA or BGRA, sRGB or UNORM; "
                  "R16G16B16A16 SFLOAT or UNORM; A2B10G10R10_UNORM)");
}

XrSwapchain create_vulkan_swapchain(XrSession session, XrSwapchainUsageFlags usage, std::int64_t format, std::uint32_t width,
                                    std::uint32_t height, std::vector<VkImage>& images, const char* what) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = usage;
    info.format = format;
    info.sampleCount = 1;
    info.width = width;
    info.height = height;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    XrSwapchain swapchain = XR_NULL_HANDLE;
    check(xrCreateSwapchain(session, &info, &swapchain), what);
    std::uint32_t count = 0;
    check(xrEnumerateSwapchainImages(swapchain, 0, &count, nullptr), "xrEnumerateSwapchainImages");
    std::vector<XrSwapchainImageVulkan2KHR> listed(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
    check(xrEnumerateSwapchainImages(swapchain, count, &count, reinterpret_cast<XrSwapchainImageBaseHeader*>(listed.data())),
          "xrEnumerateSwapchainImages");
    images.clear();
    for (const auto& img : listed) images.push_back(img.image);
    return swapchain;
}

EyeSwapchain::EyeSwapchain(XrSession session, VkFormat format, std::uint32_t width, std::uint32_t height)
    : format_(format), width_(width), height_(height) {
    swapchain_ = create_vulkan_swapchain(session, XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT,
                                         format, width, height, images_, "xrCreateSwapchain");
}

EyeSwapchain::~EyeSwapchain() {
    if (swapchain_) xrDestroySwapchain(swapchain_);
}

void EyeSwapchain::present(const vk::Context& ctx, vk::StorageImage& source) {
    std::uint32_t index = 0;
    XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    check(xrAcquireSwapchainImage(swapchain_, &acquire, &index), "xrAcquireSwapchainImage");
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    check(xrWaitSwapchainImage(swapchain_, &wait), "xrWaitSwapchainImage");
    if (index >= images_.size())
        throw XrError(XR_ERROR_RUNTIME_FAILURE, fmt::format("the runtime acquired swapchain image {} of {}", index, images_.size()));

    copy(ctx, source, images_[index], true);
    XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    check(xrReleaseSwapchainImage(swapchain_, &release), "xrReleaseSwapchainImage");
}


void EyeSwapchain::prepare(const vk::Context& ctx, vk::StorageImage& source) {
    if (!rehearsal_) rehearsal_ = std::make_unique<vk::TransferImage>(ctx, format_, VkExtent2D{width_, height_});
    copy(ctx, source, rehearsal_->handle(), false);
}

// Copies `source` into `target` as the runtime's image takes it (the same bytes, or blitted to the
// swapchain's size). The runtime's images come and go in COLOR_ATTACHMENT_OPTIMAL; prepare()'s own
// is left in TRANSFER_DST_OPTIMAL.
void EyeSwapchain::copy(const vk::Context& ctx, vk::StorageImage& source, VkImage target, bool runtime_image) {
    const VkExtent2D from = source.extent();
    // The final image's bytes are sRGB-encoded already: an R8G8B8A8_SRGB image of the same size
    // takes them as they are.
    const bool copy_as_they_are = format_ == VK_FORMAT_R8G8B8A8_SRGB && from.width == width_ && from.height == height_;
    std::unique_ptr<vk::TransferImage>& encoded = encoded_[{from.width, from.height}];
    if (!copy_as_they_are && !encoded) encoded = std::make_unique<vk::TransferImage>(ctx, VK_FORMAT_R8G8B8A8_SRGB, from);
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        // The frame graph wrote `source` in compute; the runtime hands images over in
        // COLOR_ATTACHMENT_OPTIMAL and wants them back in it.
        source.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::compute_write, vk::access::transfer_read);
        if (runtime_image)
            vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                     {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                                     vk::access::transfer_write);
        else
            rehearsal_->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, vk::access::transfer_write, vk::access::transfer_write);
        VkImageCopy region_copy{};
        region_copy.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region_copy.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region_copy.extent = {from.width, from.height, 1};
        if (copy_as_they_are) {
            vkCmdCopyImage(cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region_copy);
        } else {
            encoded->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, vk::access::transfer_read, vk::access::transfer_write);
            vkCmdCopyImage(cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, encoded->handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region_copy);
            encoded->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::transfer_write, vk::access::transfer_read);
            VkImageBlit region{};
            region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.srcOffsets[1] = {static_cast<std::int32_t>(from.width), static_cast<std::int32_t>(from.height), 1};
            region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.dstOffsets[1] = {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_), 1};
            vkCmdBlitImage(cmd, encoded->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region, VK_FILTER_LINEAR);
        }
        if (runtime_image)
            vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                     vk::access::transfer_write,
                                     {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
        // Back to GENERAL for the next frame's passes, after this read.
        source.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::transfer_read, vk::access::compute_read_write);
    });
}

}  // namespace fg::xr
