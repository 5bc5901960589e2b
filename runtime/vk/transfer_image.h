#pragma once
// A 2D colour image that only copies and blits touch (no view, no shader access): a format
// another image's texels are re-labelled as, or a hand-over between two sizes.
#include <vulkan/vulkan.h>

#include "vk/commands.h"

namespace fg::vk {

class Context;

class TransferImage {
public:
    // Throws VulkanError(VK_ERROR_FORMAT_NOT_SUPPORTED) when the device cannot copy into the
    // format and blit from it.
    TransferImage(const Context& ctx, VkFormat format, VkExtent2D extent);
    ~TransferImage();
    TransferImage(const TransferImage&) = delete;
    TransferImage& operator=(const TransferImage&) = delete;

    VkImage handle() const { return image_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }

    // Records a layout transition from the tracked layout.
    void transition(VkCommandBuffer cmd, VkImageLayout new_layout, Access src, Access dst);

private:
    const Context* ctx_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkFormat format_;
    VkExtent2D extent_;
    VkImageLayout layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
};

}  // namespace fg::vk
