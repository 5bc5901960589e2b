#include "vk/image.h"

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/memory_type.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

std::uint32_t bytes_per_pixel(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32_SFLOAT: return 4;
        case VK_FORMAT_R32G32_SFLOAT: return 8;
        case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        case VK_FORMAT_R32G32B32A32_UINT: return 16;
        case VK_FORMAT_R8G8B8A8_UNORM: return 4;
        default:
            throw std::invalid_argument(
                fmt::format("VkFormat {} is not a storage image format", static_cast<int>(format)));
    }
}

const char* format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32_SFLOAT: return "R32_SFLOAT";
        case VK_FORMAT_R32G32_SFLOAT: return "R32G32_SFLOAT";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "R16G16B16A16_SFLOAT";
        case VK_FORMAT_R32G32B32A32_SFLOAT: return "R32G32B32A32_SFLOAT";
        case VK_FORMAT_R8G8B8A8_UNORM: return "R8G8B8A8_UNORM";
        case VK_FORMAT_R32G32B32A32_UINT: return "R32G32B32A32_UINT";
        default: return "unsupported format";
    }
}

BoundImage create_bound_image(const Context& ctx, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    BoundImage bound;
    check(vkCreateImage(ctx.device(), &info, nullptr, &bound.image), "vkCreateImage");
    try {
        VkMemoryRequirements requirements{};
        vkGetImageMemoryRequirements(ctx.device(), bound.image, &requirements);
        VkMemoryAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            select_memory_type(ctx.memory_properties(), requirements.memoryTypeBits, MemoryKind::DeviceLocal);
        check(vkAllocateMemory(ctx.device(), &allocate, nullptr, &bound.memory), "vkAllocateMemory");
        check(vkBindImageMemory(ctx.device(), bound.image, bound.memory, 0), "vkBindImageMemory");
    } catch (...) {
        vkDestroyImage(ctx.device(), bound.image, nullptr);
        if (bound.memory) vkFreeMemory(ctx.device(), bound.memory, nullptr);
        throw;
    }
    return bound;
}

StorageImage::StorageImage(const Context& ctx, VkFormat format, VkExtent2D extent)
    : ctx_(&ctx), format_(format), extent_(extent) {
    fg::vk::bytes_per_pixel(format);  // rejects formats outside the list early
    if (extent.width == 0 || extent.height == 0)
        throw std::invalid_argument(fmt::format("an image cannot be {}x{}", extent.width, extent.height));

    VkFormatProperties support{};
    vkGetPhysicalDeviceFormatProperties(ctx.physical(), format, &support);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((support.optimalTilingFeatures & needed) != needed)
        throw VulkanError(VK_ERROR_FORMAT_NOT_SUPPORTED,
                          fmt::format("{} cannot use {} as a storage image", ctx.device_name(), format_name(format)));

    const BoundImage bound = create_bound_image(ctx, format, extent, kUsage);
    image_ = bound.image;
    memory_ = bound.memory;
    try {
        VkImageViewCreateInfo view_info{};
        view_info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        view_info.image = image_;
        view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view_info.format = format;
        view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        check(vkCreateImageView(ctx.device(), &view_info, nullptr, &view_), "vkCreateImageView");
    } catch (...) {
        destroy();
        throw;
    }
}

StorageImage::~StorageImage() { destroy(); }

StorageImage::StorageImage(StorageImage&& other) noexcept
    : ctx_(other.ctx_),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      view_(std::exchange(other.view_, VK_NULL_HANDLE)),
      format_(other.format_),
      extent_(other.extent_),
      layout_(other.layout_) {}

StorageImage& StorageImage::operator=(StorageImage&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        format_ = other.format_;
        extent_ = other.extent_;
        layout_ = other.layout_;
    }
    return *this;
}

void StorageImage::destroy() noexcept {
    if (view_) vkDestroyImageView(ctx_->device(), view_, nullptr);
    if (image_) vkDestroyImage(ctx_->device(), image_, nullptr);
    if (memory_) vkFreeMemory(ctx_->device(), memory_, nullptr);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

std::size_t StorageImage::byte_size() const {
    return std::size_t{extent_.width} * extent_.height * bytes_per_pixel();
}

void StorageImage::transition(VkCommandBuffer cmd, VkImageLayout new_layout, Access src, Access dst) {
    image_layout_barrier(cmd, image_, layout_, new_layout, src, dst);
    layout_ = new_layout;
}

std::vector<std::byte> StorageImage::download() {
    Buffer readback(*ctx_, byte_size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback);
    OneShot::run(*ctx_, [&](VkCommandBuffer cmd) {
        transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, access::any_write, access::transfer_read);
        VkBufferImageCopy region{};
        region.bufferRowLength = 0;  // 0 = rows tightly packed
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(cmd, image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
        transfer_to_host_barrier(cmd);
        transition(cmd, VK_IMAGE_LAYOUT_GENERAL, access::transfer_read, access::anything);
    });
    std::vector<std::byte> pixels(byte_size());
    readback.download(pixels);
    return pixels;
}

void StorageImage::upload(std::span<const std::byte> pixels) {
    if (pixels.size() != byte_size())
        throw std::invalid_argument(fmt::format("{} bytes given for a {}x{} {} image of {} bytes", pixels.size(),
                                                extent_.width, extent_.height, format_name(format_), byte_size()));
    Buffer staging(*ctx_, byte_size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
    staging.upload(pixels);
    OneShot::run(*ctx_, [&](VkCommandBuffer cmd) {
        // Old contents are overwritten whole, so they need not be kept through the transition.
        image_layout_barrier(cmd, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             access::anything, access::transfer_write);
        layout_ = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(cmd, VK_IMAGE_LAYOUT_GENERAL, access::transfer_write, access::anything);
    });
}

}  // namespace fg::vk
