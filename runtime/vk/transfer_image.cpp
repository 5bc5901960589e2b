#include "vk/transfer_image.h"

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/image.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

TransferImage::TransferImage(const Context& ctx, VkFormat format, VkExtent2D extent)
    : ctx_(&ctx), format_(format), extent_(extent) {
    VkFormatProperties support{};
    vkGetPhysicalDeviceFormatProperties(ctx.physical(), format, &support);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_TRANSFER_DST_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT;
    if ((support.optimalTilingFeatures & needed) != needed)
        throw VulkanError(VK_ERROR_FORMAT_NOT_SUPPORTED,
                          fmt::format("{} cannot copy into VkFormat {} and blit from it", ctx.device_name(), static_cast<int>(format)));

    const BoundImage bound = create_bound_image(ctx, format, extent, VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    image_ = bound.image;
    memory_ = bound.memory;
}

TransferImage::~TransferImage() {
    vkDestroyImage(ctx_->device(), image_, nullptr);
    vkFreeMemory(ctx_->device(), memory_, nullptr);
}

void TransferImage::transition(VkCommandBuffer cmd, VkImageLayout new_layout, Access src, Access dst) {
    image_layout_barrier(cmd, image_, layout_, new_layout, src, dst);
    layout_ = new_layout;
}

}  // namespace fg::vk
