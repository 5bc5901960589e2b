#include "vk/transfer_image.h"

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/memory_type.h"
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

    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(ctx.device(), &info, nullptr, &image_), "vkCreateImage");

    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(ctx.device(), image_, &requirements);
    VkMemoryAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocate.allocationSize = requirements.size;
    try {
        allocate.memoryTypeIndex = select_memory_type(ctx.memory_properties(), requirements.memoryTypeBits, MemoryKind::DeviceLocal);
        check(vkAllocateMemory(ctx.device(), &allocate, nullptr, &memory_), "vkAllocateMemory");
        check(vkBindImageMemory(ctx.device(), image_, memory_, 0), "vkBindImageMemory");
    } catch (...) {
        vkDestroyImage(ctx.device(), image_, nullptr);
        if (memory_) vkFreeMemory(ctx.device(), memory_, nullptr);
        throw;
    }
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
