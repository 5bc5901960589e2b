#include "vk/buffer.h"

#include <cstring>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vk/commands.h"
#include "vk/context.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind)
    : ctx_(&ctx), size_(size), kind_(kind) {
    if (size == 0) throw std::invalid_argument("a Vulkan buffer cannot be empty");

    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer_), "vkCreateBuffer");

    try {
        VkMemoryRequirements requirements{};
        vkGetBufferMemoryRequirements(ctx.device(), buffer_, &requirements);
        const std::uint32_t type = select_memory_type(ctx.memory_properties(), requirements.memoryTypeBits, kind);
        coherent_ = (ctx.memory_properties().memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;

        VkMemoryAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex = type;
        check(vkAllocateMemory(ctx.device(), &allocate, nullptr, &memory_), "vkAllocateMemory");
        check(vkBindBufferMemory(ctx.device(), buffer_, memory_, 0), "vkBindBufferMemory");

        // Even when device-local memory happens to be host visible (integrated GPUs, lavapipe),
        // it is not mapped: the staging path is then the one exercised everywhere.
        if (kind != MemoryKind::DeviceLocal) {
            void* mapped = nullptr;
            check(vkMapMemory(ctx.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
            mapped_ = static_cast<std::byte*>(mapped);
        }
    } catch (...) {
        destroy();
        throw;
    }
}

Buffer::~Buffer() { destroy(); }

Buffer::Buffer(Buffer&& other) noexcept
    : ctx_(other.ctx_),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      size_(std::exchange(other.size_, 0)),
      kind_(other.kind_),
      coherent_(other.coherent_),
      mapped_(std::exchange(other.mapped_, nullptr)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        kind_ = other.kind_;
        coherent_ = other.coherent_;
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void Buffer::destroy() noexcept {
    if (buffer_) vkDestroyBuffer(ctx_->device(), buffer_, nullptr);
    // Freeing the memory also unmaps it.
    if (memory_) vkFreeMemory(ctx_->device(), memory_, nullptr);
    buffer_ = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

void Buffer::require_mapped() const {
    if (!mapped_)
        throw std::logic_error(fmt::format("a {} buffer is not mapped; use upload()/download()",
                                           memory_kind_name(kind_)));
}

void Buffer::require_range(std::size_t bytes, VkDeviceSize offset) const {
    if (offset > size_ || bytes > size_ - offset)
        throw std::out_of_range(
            fmt::format("{} bytes at offset {} do not fit in a buffer of {} bytes", bytes, offset, size_));
}

void Buffer::flush() {
    require_mapped();
    if (coherent_) return;
    VkMappedMemoryRange range{};
    range.sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE;
    range.memory = memory_;
    range.size = VK_WHOLE_SIZE;
    check(vkFlushMappedMemoryRanges(ctx_->device(), 1, &range), "vkFlushMappedMemoryRanges");
}

void Buffer::invalidate() const {
    require_mapped();
    if (coherent_) return;
    VkMappedMemoryRange range{};
    range.sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE;
    range.memory = memory_;
    range.size = VK_WHOLE_SIZE;
    check(vkInvalidateMappedMemoryRanges(ctx_->device(), 1, &range), "vkInvalidateMappedMemoryRanges");
}

void Buffer::upload(std::span<const std::byte> bytes, VkDeviceSize offset) {
    require_range(bytes.size(), offset);
    if (bytes.empty()) return;
    if (mapped_) {
        std::memcpy(mapped_ + offset, bytes.data(), bytes.size());
        flush();
        return;
    }

    Buffer staging(*ctx_, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::HostVisible);
    staging.upload(bytes);
    OneShot::run(*ctx_, [&](VkCommandBuffer cmd) {
        // Work submitted earlier may still read or write this buffer.
        memory_barrier(cmd, access::anything, access::transfer_write);
        const VkBufferCopy region{0, offset, bytes.size()};
        vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &region);
        memory_barrier(cmd, access::transfer_write, access::anything);
    });
}

void Buffer::download(std::span<std::byte> bytes, VkDeviceSize offset) const {
    require_range(bytes.size(), offset);
    if (bytes.empty()) return;
    if (mapped_) {
        invalidate();
        std::memcpy(bytes.data(), mapped_ + offset, bytes.size());
        return;
    }

    Buffer staging(*ctx_, bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback);
    OneShot::run(*ctx_, [&](VkCommandBuffer cmd) {
        memory_barrier(cmd, access::any_write, access::transfer_read);
        const VkBufferCopy region{offset, 0, bytes.size()};
        vkCmdCopyBuffer(cmd, buffer_, staging.handle(), 1, &region);
        transfer_to_host_barrier(cmd);
    });
    staging.download(bytes);
}

}  // namespace fg::vk
