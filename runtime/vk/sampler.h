#pragma once
// A VkSampler for reading a StorageImage through a combined image sampler (palettes, previous
// frames), as opposed to imageLoad.
#include <vulkan/vulkan.h>

namespace fg::vk {

class Context;

class Sampler {
public:
    explicit Sampler(const Context& ctx, VkFilter filter = VK_FILTER_NEAREST,
                     VkSamplerAddressMode address_mode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
    ~Sampler();
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;
    Sampler(Sampler&& other) noexcept;
    Sampler& operator=(Sampler&& other) noexcept;

    VkSampler handle() const { return sampler_; }

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace fg::vk
