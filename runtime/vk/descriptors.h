#pragma once
// Descriptor set layouts described as plain lists of bindings, a pool to allocate sets from, and
// one write helper per kind of resource a compute pass binds.
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

class Buffer;
class Context;
class Sampler;
class StorageImage;

struct DescriptorBinding {
    std::uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    VkShaderStageFlags stages = VK_SHADER_STAGE_COMPUTE_BIT;
    std::uint32_t count = 1;  // array size in the shader
};

class DescriptorSetLayout {
public:
    // Throws std::invalid_argument when a binding number is used twice.
    DescriptorSetLayout(const Context& ctx, std::vector<DescriptorBinding> bindings);
    ~DescriptorSetLayout();
    DescriptorSetLayout(const DescriptorSetLayout&) = delete;
    DescriptorSetLayout& operator=(const DescriptorSetLayout&) = delete;
    DescriptorSetLayout(DescriptorSetLayout&& other) noexcept;
    DescriptorSetLayout& operator=(DescriptorSetLayout&& other) noexcept;

    VkDescriptorSetLayout handle() const { return layout_; }
    const std::vector<DescriptorBinding>& bindings() const { return bindings_; }

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
    std::vector<DescriptorBinding> bindings_;
};

// Descriptor counts, by type, for `sets` sets made from `bindings`.
std::vector<VkDescriptorPoolSize> pool_sizes(std::span<const DescriptorBinding> bindings, std::uint32_t sets);

// Sets are not freed one by one; they go back all together with reset() or the pool's end.
class DescriptorPool {
public:
    DescriptorPool(const Context& ctx, std::uint32_t max_sets, std::span<const VkDescriptorPoolSize> sizes);
    // Room for `sets` sets of `layout`.
    DescriptorPool(const Context& ctx, const DescriptorSetLayout& layout, std::uint32_t sets);
    ~DescriptorPool();
    DescriptorPool(const DescriptorPool&) = delete;
    DescriptorPool& operator=(const DescriptorPool&) = delete;
    DescriptorPool(DescriptorPool&& other) noexcept;
    DescriptorPool& operator=(DescriptorPool&& other) noexcept;

    VkDescriptorPool handle() const { return pool_; }
    // Throws VulkanError (VK_ERROR_OUT_OF_POOL_MEMORY) when the pool is full.
    VkDescriptorSet allocate(const DescriptorSetLayout& layout);
    void reset();

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

void write_storage_buffer(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const Buffer& buffer,
                          VkDeviceSize offset = 0, VkDeviceSize range = VK_WHOLE_SIZE);
void write_uniform_buffer(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const Buffer& buffer,
                          VkDeviceSize offset = 0, VkDeviceSize range = VK_WHOLE_SIZE);
// Storage images are always accessed in GENERAL layout.
void write_storage_image(const Context& ctx, VkDescriptorSet set, std::uint32_t binding, const StorageImage& image);
// `layout` is the one the image will be in when the shader samples it.
void write_combined_image_sampler(const Context& ctx, VkDescriptorSet set, std::uint32_t binding,
                                  const Sampler& sampler, const StorageImage& image,
                                  VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

}  // namespace fg::vk
