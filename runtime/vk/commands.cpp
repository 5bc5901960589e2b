#include "vk/commands.h"

#include <utility>

#include "vk/context.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

// --- CommandPool ---------------------------------------------------------------------------

CommandPool::CommandPool(const Context& ctx, VkCommandPoolCreateFlags flags) : ctx_(&ctx) {
    VkCommandPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    info.flags = flags;
    info.queueFamilyIndex = ctx.queue_family();
    check(vkCreateCommandPool(ctx.device(), &info, nullptr, &pool_), "vkCreateCommandPool");
}

CommandPool::~CommandPool() { destroy(); }

CommandPool::CommandPool(CommandPool&& other) noexcept
    : ctx_(other.ctx_), pool_(std::exchange(other.pool_, VK_NULL_HANDLE)) {}

CommandPool& CommandPool::operator=(CommandPool&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    }
    return *this;
}

void CommandPool::destroy() noexcept {
    if (pool_) vkDestroyCommandPool(ctx_->device(), pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

VkCommandBuffer CommandPool::allocate() {
    VkCommandBufferAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    info.commandPool = pool_;
    info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    info.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(ctx_->device(), &info, &cmd), "vkAllocateCommandBuffers");
    return cmd;
}

void CommandPool::reset() { check(vkResetCommandPool(ctx_->device(), pool_, 0), "vkResetCommandPool"); }

// --- Fence ---------------------------------------------------------------------------------

Fence::Fence(const Context& ctx, bool signaled) : ctx_(&ctx) {
    VkFenceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    info.flags = signaled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
    check(vkCreateFence(ctx.device(), &info, nullptr, &fence_), "vkCreateFence");
}

Fence::~Fence() { destroy(); }

Fence::Fence(Fence&& other) noexcept : ctx_(other.ctx_), fence_(std::exchange(other.fence_, VK_NULL_HANDLE)) {}

Fence& Fence::operator=(Fence&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        fence_ = std::exchange(other.fence_, VK_NULL_HANDLE);
    }
    return *this;
}

void Fence::destroy() noexcept {
    if (fence_) vkDestroyFence(ctx_->device(), fence_, nullptr);
    fence_ = VK_NULL_HANDLE;
}

void Fence::wait(std::uint64_t timeout_ns) const {
    const VkResult result = vkWaitForFences(ctx_->device(), 1, &fence_, VK_TRUE, timeout_ns);
    if (result == VK_TIMEOUT) throw VulkanError(result, "vkWaitForFences failed: VK_TIMEOUT");
    check(result, "vkWaitForFences");
}

void Fence::reset() { check(vkResetFences(ctx_->device(), 1, &fence_), "vkResetFences"); }

// --- OneShot -------------------------------------------------------------------------------

OneShot::OneShot(const Context& ctx)
    : ctx_(&ctx), pool_(ctx, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT), fence_(ctx) {
    cmd_ = pool_.allocate();
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
}

OneShot::~OneShot() {
    // The pool (and the command buffer in it) must not be destroyed under a running GPU, even
    // when an exception cut the wait short.
    if (in_flight_) {
        const VkFence fence = fence_.handle();
        vkWaitForFences(ctx_->device(), 1, &fence, VK_TRUE, UINT64_MAX);
    }
}

void OneShot::submit_and_wait(std::uint64_t timeout_ns) {
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    ctx_->submit(cmd_, fence_.handle());
    in_flight_ = true;
    fence_.wait(timeout_ns);
    in_flight_ = false;
}

void OneShot::run(const Context& ctx, const std::function<void(VkCommandBuffer)>& record) {
    OneShot shot(ctx);
    record(shot.cmd());
    shot.submit_and_wait();
}

// --- Barriers ------------------------------------------------------------------------------

void memory_barrier(VkCommandBuffer cmd, Access src, Access dst) {
    VkMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2;
    barrier.srcStageMask = src.stage;
    barrier.srcAccessMask = src.access;
    barrier.dstStageMask = dst.stage;
    barrier.dstAccessMask = dst.access;

    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

void compute_to_compute_barrier(VkCommandBuffer cmd) {
    memory_barrier(cmd, access::compute_write, access::compute_read_write);
}

void compute_to_transfer_barrier(VkCommandBuffer cmd) {
    memory_barrier(cmd, access::compute_write, {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                                VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT});
}

void transfer_to_compute_barrier(VkCommandBuffer cmd) {
    memory_barrier(cmd, access::transfer_write, access::compute_read_write);
}

void transfer_to_host_barrier(VkCommandBuffer cmd) { memory_barrier(cmd, access::transfer_write, access::host_read); }

void compute_to_host_barrier(VkCommandBuffer cmd) { memory_barrier(cmd, access::compute_write, access::host_read); }

void image_layout_barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout old_layout, VkImageLayout new_layout,
                          Access src, Access dst) {
    VkImageMemoryBarrier2 barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2;
    barrier.srcStageMask = src.stage;
    barrier.srcAccessMask = src.access;
    barrier.dstStageMask = dst.stage;
    barrier.dstAccessMask = dst.access;
    barrier.oldLayout = old_layout;
    barrier.newLayout = new_layout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

    VkDependencyInfo dependency{};
    dependency.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO;
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace fg::vk
