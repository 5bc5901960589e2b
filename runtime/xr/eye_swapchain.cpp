#include "xr/eye_swapchain.h"

#include <algorithm>
#include <fmt/format.h>

#include "vk/commands.h"
#include "xr/xr_error.h"

namespace fg::xr {

std::int64_t choose_swapchain_format(const std::vector<std::int64_t>& offered) {
    for (VkFormat f : {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB})
        if (std::find(offered.begin(), offered.end(), static_cast<std::int64_t>(f)) != offered.end()) return f;
    throw XrError(XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED,
                  "the OpenXR runtime offers no 8-bit RGBA swapchain format (R8G8B8A8 or B8G8R8A8, UNORM or SRGB)");
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

EyeSwapchain::EyeSwapchain(XrSession session, std::int64_t format, std::uint32_t width, std::uint32_t height)
    : width_(width), height_(height) {
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

    VkImage target = images_[index];
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        // The frame graph wrote `source` in compute; the runtime hands images over in
        // COLOR_ATTACHMENT_OPTIMAL and wants them back in it.
        source.transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::compute_write, vk::access::transfer_read);
        vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
                                 vk::access::transfer_write);
        VkImageBlit region{};
        region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.srcOffsets[1] = {static_cast<std::int32_t>(source.extent().width),
                                static_cast<std::int32_t>(source.extent().height), 1};
        region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.dstOffsets[1] = {static_cast<std::int32_t>(width_), static_cast<std::int32_t>(height_), 1};
        vkCmdBlitImage(cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
                       VK_FILTER_LINEAR);
        vk::image_layout_barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                 vk::access::transfer_write,
                                 {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
        // Back to GENERAL for the next frame's passes, after this read.
        source.transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::transfer_read, vk::access::compute_read_write);
    });
    XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    check(xrReleaseSwapchainImage(swapchain_, &release), "xrReleaseSwapchainImage");
}

}  // namespace fg::xr
