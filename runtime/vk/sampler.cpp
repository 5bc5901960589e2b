#include "vk/sampler.h"

#include <utility>

#include "vk/context.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

Sampler::Sampler(const Context& ctx, VkFilter filter, VkSamplerAddressMode address_mode) : ctx_(&ctx) {
    VkSamplerCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = address_mode;
    info.addressModeV = address_mode;
    info.addressModeW = address_mode;
    info.maxLod = 0.0f;  // StorageImage has a single mip level
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    check(vkCreateSampler(ctx.device(), &info, nullptr, &sampler_), "vkCreateSampler");
}

Sampler::~Sampler() { destroy(); }

Sampler::Sampler(Sampler&& other) noexcept
    : ctx_(other.ctx_), sampler_(std::exchange(other.sampler_, VK_NULL_HANDLE)) {}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
    }
    return *this;
}

void Sampler::destroy() noexcept {
    if (sampler_) vkDestroySampler(ctx_->device(), sampler_, nullptr);
    sampler_ = VK_NULL_HANDLE;
}

}  // namespace fg::vk
