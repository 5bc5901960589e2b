#pragma once
// Recording and submitting work: a command pool, a fence, a one-shot "record, submit, wait"
// helper, and synchronization2 barriers for the hand-offs compute work needs.
#include <cstdint>
#include <functional>

#include <vulkan/vulkan.h>

namespace fg::vk {

class Context;

class CommandPool {
public:
    explicit CommandPool(const Context& ctx,
                         VkCommandPoolCreateFlags flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    ~CommandPool();
    CommandPool(const CommandPool&) = delete;
    CommandPool& operator=(const CommandPool&) = delete;
    CommandPool(CommandPool&& other) noexcept;
    CommandPool& operator=(CommandPool&& other) noexcept;

    VkCommandPool handle() const { return pool_; }
    // A primary command buffer; it is freed with the pool.
    VkCommandBuffer allocate();
    void reset();

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkCommandPool pool_ = VK_NULL_HANDLE;
};

class Fence {
public:
    explicit Fence(const Context& ctx, bool signaled = false);
    ~Fence();
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;
    Fence(Fence&& other) noexcept;
    Fence& operator=(Fence&& other) noexcept;

    VkFence handle() const { return fence_; }
    // Throws VulkanError(VK_TIMEOUT) when the timeout passes first.
    void wait(std::uint64_t timeout_ns = UINT64_MAX) const;
    void reset();

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkFence fence_ = VK_NULL_HANDLE;
};

// Records into a fresh command buffer from its own transient pool (so one-shots on different
// threads never share a pool), then submits and blocks until the GPU is done.
//
//     OneShot::run(ctx, [&](VkCommandBuffer cmd) { vkCmdCopyBuffer(cmd, ...); });
class OneShot {
public:
    explicit OneShot(const Context& ctx);  // begins recording
    ~OneShot();
    OneShot(const OneShot&) = delete;
    OneShot& operator=(const OneShot&) = delete;
    // Scoped to one block of recording; not moved around.
    OneShot(OneShot&&) = delete;
    OneShot& operator=(OneShot&&) = delete;

    VkCommandBuffer cmd() const { return cmd_; }
    void submit_and_wait(std::uint64_t timeout_ns = UINT64_MAX);

    static void run(const Context& ctx, const std::function<void(VkCommandBuffer)>& record);

private:
    const Context* ctx_;
    CommandPool pool_;
    Fence fence_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    bool in_flight_ = false;
};

// One side of a dependency: where in the pipeline, and which kind of memory access.
struct Access {
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

namespace access {
inline constexpr Access none{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
inline constexpr Access compute_read{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                     VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                                         VK_ACCESS_2_UNIFORM_READ_BIT};
inline constexpr Access compute_write{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr Access compute_read_write{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                           compute_read.access | compute_write.access};
inline constexpr Access transfer_read{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
inline constexpr Access transfer_write{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
inline constexpr Access host_read{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
inline constexpr Access host_write{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT};
// For when the previous (or next) user of a resource is not known.
inline constexpr Access anything{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                 VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
inline constexpr Access any_write{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT};
}  // namespace access

// A global memory barrier (vkCmdPipelineBarrier2): writes done at `src` become visible to `dst`.
void memory_barrier(VkCommandBuffer cmd, Access src, Access dst);

// Storage writes of one dispatch visible to the next.
void compute_to_compute_barrier(VkCommandBuffer cmd);
// Storage writes of a dispatch visible to a following copy.
void compute_to_transfer_barrier(VkCommandBuffer cmd);
// An upload copy visible to a following dispatch.
void transfer_to_compute_barrier(VkCommandBuffer cmd);
// A copy into host-visible memory visible to the CPU after the fence wait.
void transfer_to_host_barrier(VkCommandBuffer cmd);
// Storage writes into mapped memory visible to the CPU after the fence wait.
void compute_to_host_barrier(VkCommandBuffer cmd);

// Layout transition of the first mip level and array layer of a color image.
void image_layout_barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout old_layout, VkImageLayout new_layout,
                          Access src, Access dst);

}  // namespace fg::vk
