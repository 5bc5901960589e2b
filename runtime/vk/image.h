#pragma once
// A 2D image that compute shaders write with imageStore and that can be sampled, copied and read
// back. Its layout is tracked in recording order so callers only name the layout they need next.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/commands.h"

namespace fg::vk {

class Context;

// Bytes of one pixel of a format StorageImage accepts; throws std::invalid_argument otherwise.
std::uint32_t bytes_per_pixel(VkFormat format);
const char* format_name(VkFormat format);

// A 2D, single-level, optimally tiled colour image of `usage` in device-local memory, bound to it;
// on failure nothing is left behind. StorageImage and TransferImage each hold one.
struct BoundImage {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
};
BoundImage create_bound_image(const Context& ctx, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage);

class StorageImage {
public:
    static constexpr VkImageUsageFlags kUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;

    // Formats: R32_SFLOAT, R32G32_SFLOAT, R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT, R8G8B8A8_UNORM.
    // Throws VulkanError(VK_ERROR_FORMAT_NOT_SUPPORTED) when the device cannot use the format for
    // storage, sampling and copies.
    StorageImage(const Context& ctx, VkFormat format, VkExtent2D extent);
    ~StorageImage();
    StorageImage(const StorageImage&) = delete;
    StorageImage& operator=(const StorageImage&) = delete;
    StorageImage(StorageImage&& other) noexcept;
    StorageImage& operator=(StorageImage&& other) noexcept;

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    std::uint32_t bytes_per_pixel() const { return fg::vk::bytes_per_pixel(format_); }
    std::size_t byte_size() const;  // of the tightly packed pixels

    // The layout the image will be in once everything recorded so far has run.
    VkImageLayout layout() const { return layout_; }
    // Records a layout transition from the tracked layout (a plain barrier when it is already in
    // `new_layout`).
    void transition(VkCommandBuffer cmd, VkImageLayout new_layout, Access src, Access dst);

    // Blocking copies of tightly packed rows. Both leave the image in GENERAL, ready for
    // imageLoad/imageStore.
    std::vector<std::byte> download();
    void upload(std::span<const std::byte> pixels);

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    VkImageLayout layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
};

}  // namespace fg::vk
