#include "vk/descriptors.h"

#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/sampler.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

// --- DescriptorSetLayout -------------------------------------------------------------------

DescriptorSetLayout::DescriptorSetLayout(const Context& ctx, std::vector<DescriptorBinding> bindings)
    : ctx_(&ctx), bindings_(std::move(bindings)) {
    std::set<std::uint32_t> seen;
    std::vector<VkDescriptorSetLayoutBinding> vk_bindings;
    for (const DescriptorBinding& b : bindings_) {
        if (!seen.insert(b.binding).second)
            throw std::invalid_argument(fmt::format("descriptor binding {} is listed twice", b.binding));
        VkDescriptorSetLayoutBinding vk_binding{};
        vk_binding.binding = b.binding;
        vk_binding.descriptorType = b.type;
        vk_binding.descriptorCount = b.count;
        vk_binding.stageFlags = b.stages;
        vk_bindings.push_back(vk_binding);
    }

    VkDescriptorSetLayoutCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    info.bindingCount = static_cast<std::uint32_t>(vk_bindings.size());
    info.pBindings = vk_bindings.data();
    check(vkCreateDescriptorSetLayout(ctx.device(), &info, nullptr, &layout_), "vkCreateDescriptorSetLayout");
}

DescriptorSetLayout::~DescriptorSetLayout() { destroy(); }

DescriptorSetLayout::DescriptorSetLayout(DescriptorSetLayout&& other) noexcept
    : ctx_(other.ctx_),
      layout_(std::exchange(other.layout_, VK_NULL_HANDLE)),
      bindings_(std::move(other.bindings_)) {}

DescriptorSetLayout& DescriptorSetLayout::operator=(DescriptorSetLayout&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
        bindings_ = std::move(other.bindings_);
    }
    return *this;
}

void DescriptorSetLayout::destroy() noexcept {
    if (layout_) vkDestroyDescriptorSetLayout(ctx_->device(), layout_, nullptr);
    layout_ = VK_NULL_HANDLE;
}

// --- DescriptorPool ------------------------------------------------------------------------

std::vector<VkDescriptorPoolSize> pool_sizes(std::span<const DescriptorBinding> bindings, std::uint32_t sets) {
    std::map<VkDescriptorType, std::uint32_t> counts;
    for (const DescriptorBinding& b : bindings) counts[b.type] += b.count * sets;
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, count] : counts) sizes.push_back({type, count});
    return sizes;
}

DescriptorPool::DescriptorPool(const Context& ctx, std::uint32_t max_sets, std::span<const VkDescriptorPoolSize> sizes)
    : ctx_(&ctx) {
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = max_sets;
    info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    check(vkCreateDescriptorPool(ctx.device(), &info, nullptr, &pool_), "vkCreateDescriptorPool");
}

DescriptorPool::DescriptorPool(const Context& ctx, const DescriptorSetLayout& layout, std::uint32_t sets)
    : DescriptorPool(ctx, sets, pool_sizes(layout.bindings(), sets)) {}

DescriptorPool::~DescriptorPool() { destroy(); }

DescriptorPool::DescriptorPool(DescriptorPool&& other) noexcept
    : ctx_(other.ctx_), pool_(std::exchange(other.pool_, VK_NULL_HANDLE)) {}

DescriptorPool& DescriptorPool::operator=(DescriptorPool&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    }
    return *this;
}

void DescriptorPool::destroy() noexcept {
    if (pool_) vkDestroyDescriptorPool(ctx_->device(), pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

VkDescriptorSet DescriptorPool::allocate(const DescriptorSetLayout& layout) {
    const VkDescriptorSetLayout handle = layout.handle();
    VkDescriptorSetAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    info.descriptorPool = pool_;
    info.descriptorSetCount = 1;
    info.pSetLayouts = &handle;
    VkDescriptorSet set = VK_NULL_HANDLE;
    check(vkAllocateDescriptorSets(ctx_->device(), &info, &set), "vkAllocateDescriptorSets");
    return set;
}

void DescriptorPool::reset() { check(vkResetDescriptorPool(ctx_->device(), pool_, 0), "vkResetDescriptorPool"); }

// --- Writes --------------------------------------------------------------------------------

namespace {

void write_buffer(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type,
                  const Buffer& buffer, VkDeviceSize offset, VkDeviceSize range) {
    const VkDescriptorBufferInfo info{buffer.handle(), offset, range};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    write.pBufferInfo = &info;
    vkUpdateDescriptorSets(ctx.device(), 1, &write, 0, nullptr);
}

void write_image(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, VkDescriptorType type,
                 VkSampler sampler, VkImageView view, VkImageLayout layout) {
    const VkDescriptorImageInfo info{sampler, view, layout};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    write.pImageInfo = &info;
    vkUpdateDescriptorSets(ctx.device(), 1, &write, 0, nullptr);
}

}  // namespace

void write_storage_buffer(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const Buffer& buffer,
                          VkDeviceSize offset, VkDeviceSize range) {
    write_buffer(ctx, set, binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer, offset, range);
}

void write_uniform_buffer(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const Buffer& buffer,
                          VkDeviceSize offset, VkDeviceSize range) {
    write_buffer(ctx, set, binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffer, offset, range);
}

void write_storage_image(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const StorageImage& image) {
    write_image(ctx, set, binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_NULL_HANDLE, image.view(),
                VK_IMAGE_LAYOUT_GENERAL);
}

void write_combined_image_sampler(const Context& ctx, VkDescriptorSet set, std::uint32_t binding,
                                  const Sampler& sampler, const StorageImage& image, VkImageLayout layout) {
    write_image(ctx, set, binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sampler.handle(), image.view(), layout);
}

}  // namespace fg::vk
