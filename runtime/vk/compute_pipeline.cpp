#include "vk/compute_pipeline.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/vulkan_error.h"

namespace fg::vk {

namespace {

constexpr std::uint32_t kSpirvMagic = 0x07230203;

std::uint32_t specialization_bits(const SpecializationValue& value) {
    return std::visit([](auto v) { return std::bit_cast<std::uint32_t>(v); }, value.value);
}

// Owns a VkShaderModule only for the time it takes to build the pipeline.
class ShaderModule {
public:
    ShaderModule(VkDevice device, std::span<const std::uint32_t> spirv) : device_(device) {
        VkShaderModuleCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
        info.codeSize = spirv.size_bytes();
        info.pCode = spirv.data();
        check(vkCreateShaderModule(device, &info, nullptr, &module_), "vkCreateShaderModule");
    }
    ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;

    VkShaderModule handle() const { return module_; }

private:
    VkDevice device_;
    VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace

// --- SpecializationValues ------------------------------------------------------------------

SpecializationValues::SpecializationValues(std::initializer_list<SpecializationValue> list) {
    for (const SpecializationValue& v : list) {
        const bool repeated = std::any_of(values.begin(), values.end(),
                                          [&](const SpecializationValue& seen) { return seen.id == v.id; });
        if (repeated) throw std::invalid_argument(fmt::format("specialization constant {} is given twice", v.id));
        values.push_back(v);
    }
}

namespace {

template <class T>
void set_value(std::vector<SpecializationValue>& values, std::uint32_t id, T value) {
    for (SpecializationValue& v : values) {
        if (v.id == id) {
            v.value = value;
            return;
        }
    }
    values.push_back({id, value});
}

}  // namespace

SpecializationValues& SpecializationValues::set(std::uint32_t id, std::uint32_t value) {
    set_value(values, id, value);
    return *this;
}

SpecializationValues& SpecializationValues::set(std::uint32_t id, std::int32_t value) {
    set_value(values, id, value);
    return *this;
}

SpecializationValues& SpecializationValues::set(std::uint32_t id, float value) {
    set_value(values, id, value);
    return *this;
}

// --- ComputePipeline -----------------------------------------------------------------------

ComputePipeline::ComputePipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                                 const std::vector<VkDescriptorSetLayout>& set_layouts,
                                 std::uint32_t push_constant_size, const SpecializationValues& specialization)
    : ctx_(&ctx), push_constant_size_(push_constant_size) {
    if (spirv.empty() || spirv[0] != kSpirvMagic)
        throw std::invalid_argument("compute shader is not SPIR-V (no magic number 0x07230203)");
    const std::uint32_t limit = ctx.limits().maxPushConstantsSize;
    if (push_constant_size > limit)
        throw std::invalid_argument(fmt::format("push constants of {} bytes exceed the limit of {} bytes on {}",
                                                push_constant_size, limit, ctx.device_name()));
    if (push_constant_size % 4 != 0)
        throw std::invalid_argument(
            fmt::format("push-constant size {} is not a multiple of 4 bytes", push_constant_size));

    const VkPushConstantRange push_range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_size};
    VkPipelineLayoutCreateInfo layout_info{};
    layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout_info.setLayoutCount = static_cast<std::uint32_t>(set_layouts.size());
    layout_info.pSetLayouts = set_layouts.data();
    layout_info.pushConstantRangeCount = push_constant_size > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &push_range;
    check(vkCreatePipelineLayout(ctx.device(), &layout_info, nullptr, &layout_), "vkCreatePipelineLayout");

    try {
        std::vector<std::uint32_t> data;
        std::vector<VkSpecializationMapEntry> entries;
        for (const SpecializationValue& v : specialization.values) {
            entries.push_back({v.id, static_cast<std::uint32_t>(data.size() * sizeof(std::uint32_t)),
                               sizeof(std::uint32_t)});
            data.push_back(specialization_bits(v));
        }
        VkSpecializationInfo specialization_info{};
        specialization_info.mapEntryCount = static_cast<std::uint32_t>(entries.size());
        specialization_info.pMapEntries = entries.data();
        specialization_info.dataSize = data.size() * sizeof(std::uint32_t);
        specialization_info.pData = data.data();

        const ShaderModule module(ctx.device(), spirv);
        VkComputePipelineCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
        info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        info.stage.module = module.handle();
        info.stage.pName = "main";
        info.stage.pSpecializationInfo = entries.empty() ? nullptr : &specialization_info;
        info.layout = layout_;
        check(vkCreateComputePipelines(ctx.device(), ctx.pipeline_cache(), 1, &info, nullptr, &pipeline_),
              "vkCreateComputePipelines");
    } catch (...) {
        destroy();
        throw;
    }
}

ComputePipeline::~ComputePipeline() { destroy(); }

ComputePipeline::ComputePipeline(ComputePipeline&& other) noexcept
    : ctx_(other.ctx_),
      layout_(std::exchange(other.layout_, VK_NULL_HANDLE)),
      pipeline_(std::exchange(other.pipeline_, VK_NULL_HANDLE)),
      push_constant_size_(other.push_constant_size_) {}

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& other) noexcept {
    if (this != &other) {
        destroy();
        ctx_ = other.ctx_;
        layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
        pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
        push_constant_size_ = other.push_constant_size_;
    }
    return *this;
}

void ComputePipeline::destroy() noexcept {
    if (pipeline_) vkDestroyPipeline(ctx_->device(), pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_->device(), layout_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
}

void ComputePipeline::bind(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    if (!sets.empty())
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0,
                                static_cast<std::uint32_t>(sets.size()), sets.data(), 0, nullptr);
}

void ComputePipeline::push_constants(VkCommandBuffer cmd, std::span<const std::byte> bytes) const {
    if (bytes.size() > push_constant_size_)
        throw std::invalid_argument(fmt::format("{} bytes of push constants for a pipeline that declared {}",
                                                bytes.size(), push_constant_size_));
    if (bytes.size() % 4 != 0)
        throw std::invalid_argument(fmt::format("{} bytes of push constants is not a multiple of 4", bytes.size()));
    if (bytes.empty()) return;
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, static_cast<std::uint32_t>(bytes.size()),
                       bytes.data());
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets, GroupCount groups,
                               std::span<const std::byte> push) const {
    bind(cmd, sets);
    push_constants(cmd, push);
    vkCmdDispatch(cmd, groups.x, groups.y, groups.z);
}

void ComputePipeline::dispatch_indirect(VkCommandBuffer cmd, VkDescriptorSet set, VkBuffer args, VkDeviceSize offset,
                                        std::span<const std::byte> push) const {
    bind(cmd, std::span<const VkDescriptorSet>(&set, 1));
    push_constants(cmd, push);
    vkCmdDispatchIndirect(cmd, args, offset);
}

}  // namespace fg::vk
