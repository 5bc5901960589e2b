#pragma once
// A VkBuffer with its own VkDeviceMemory. Host-visible kinds stay mapped for their whole life;
// device-local buffers are filled and read through staging copies.
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <span>
#include <type_traits>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/memory_type.h"

namespace fg::vk {

class Context;

class Buffer {
public:
    // `usage` gets TRANSFER_SRC | TRANSFER_DST added so any buffer can be staged and read back.
    // Throws std::invalid_argument for a zero size (Vulkan forbids empty buffers).
    Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind);
    ~Buffer();
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;

    VkBuffer handle() const { return buffer_; }
    VkDeviceMemory memory() const { return memory_; }
    VkDeviceSize size() const { return size_; }
    MemoryKind kind() const { return kind_; }
    bool is_mapped() const { return mapped_ != nullptr; }

    // The persistent mapping; nullptr for DeviceLocal. Writes through it to non-coherent
    // memory need flush(), and reads of GPU results need invalidate() first.
    std::byte* data() { return mapped_; }
    const std::byte* data() const { return mapped_; }
    // The mapping seen as T; throws std::logic_error for a DeviceLocal buffer.
    template <class T>
    std::span<T> map() {
        static_assert(std::is_trivially_copyable_v<T>);
        require_mapped();
        return {reinterpret_cast<T*>(mapped_), static_cast<std::size_t>(size_ / sizeof(T))};
    }
    void flush();
    void invalidate() const;

    // Copy host bytes in or out at `offset`; blocks until done. Throws std::out_of_range when
    // the range does not fit in the buffer.
    void upload(std::span<const std::byte> bytes, VkDeviceSize offset = 0);
    void download(std::span<std::byte> bytes, VkDeviceSize offset = 0) const;

    template <std::ranges::contiguous_range Range>
        requires std::is_trivially_copyable_v<std::ranges::range_value_t<Range>>
    void upload(const Range& values, VkDeviceSize offset = 0) {
        upload(std::as_bytes(std::span(std::ranges::data(values), std::ranges::size(values))), offset);
    }
    template <class T>
    std::vector<T> download_as(std::size_t count, VkDeviceSize offset = 0) const {
        static_assert(std::is_trivially_copyable_v<T>);
        std::vector<T> values(count);
        download(std::as_writable_bytes(std::span(values)), offset);
        return values;
    }

private:
    void require_mapped() const;
    void require_range(std::size_t bytes, VkDeviceSize offset) const;
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    MemoryKind kind_ = MemoryKind::DeviceLocal;
    bool coherent_ = true;
    std::byte* mapped_ = nullptr;
};

}  // namespace fg::vk
