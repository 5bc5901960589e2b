#pragma once
// A compute pipeline built from SPIR-V words, with its layout, specialization constants and
// the calls that bind it and dispatch it.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include <vulkan/vulkan.h>

namespace fg::vk {

class Context;

// One `layout(constant_id = id) const ...` value. Specialization constants are 4 bytes for the
// types the compiler emits (uint, int, float; bool is a 4-byte VkBool32, pass 0u or 1u).
struct SpecializationValue {
    std::uint32_t id = 0;
    std::variant<std::uint32_t, std::int32_t, float> value;
};

struct SpecializationValues {
    SpecializationValues() = default;
    // Throws std::invalid_argument when an id repeats.
    SpecializationValues(std::initializer_list<SpecializationValue> list);

    // Adds the value, or replaces the one with the same id.
    SpecializationValues& set(std::uint32_t id, std::uint32_t value);
    SpecializationValues& set(std::uint32_t id, std::int32_t value);
    SpecializationValues& set(std::uint32_t id, float value);

    bool empty() const { return values.empty(); }

    std::vector<SpecializationValue> values;
};

struct GroupCount {
    std::uint32_t x = 1;
    std::uint32_t y = 1;
    std::uint32_t z = 1;
};

// Workgroups needed to cover `items` invocations with groups of `local_size`.
constexpr std::uint32_t groups_for(std::uint32_t items, std::uint32_t local_size) {
    return (items + local_size - 1) / local_size;
}

// A value's bytes, for push constants.
template <class T>
std::span<const std::byte> bytes_of(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    return std::as_bytes(std::span<const T, 1>(&value, 1));
}

class ComputePipeline {
public:
    // `spirv` must use entry point "main". Throws std::invalid_argument when the words are not
    // SPIR-V, or the push-constant size is not a multiple of 4 or exceeds the device limit.
    ComputePipeline(const Context& ctx, std::span<const std::uint32_t> spirv,
                    const std::vector<VkDescriptorSetLayout>& set_layouts, std::uint32_t push_constant_size = 0,
                    const SpecializationValues& specialization = {});
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;
    ComputePipeline(ComputePipeline&& other) noexcept;
    ComputePipeline& operator=(ComputePipeline&& other) noexcept;

    VkPipeline pipeline() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    std::uint32_t push_constant_size() const { return push_constant_size_; }

    // Binds the pipeline and `sets` (as sets 0, 1, ...).
    void bind(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets) const;
    // Throws std::invalid_argument when `bytes` is larger than the declared push-constant size.
    void push_constants(VkCommandBuffer cmd, std::span<const std::byte> bytes) const;

    // bind + push_constants (when given) + vkCmdDispatch.
    void dispatch(VkCommandBuffer cmd, std::span<const VkDescriptorSet> sets, GroupCount groups,
                  std::span<const std::byte> push = {}) const;
    void dispatch(VkCommandBuffer cmd, VkDescriptorSet set, GroupCount groups,
                  std::span<const std::byte> push = {}) const {
        dispatch(cmd, std::span<const VkDescriptorSet>(&set, 1), groups, push);
    }

    // bind + push_constants + vkCmdDispatchIndirect: the group counts come from `args` at
    // `offset` (three uint32), written by an earlier dispatch.
    void dispatch_indirect(VkCommandBuffer cmd, VkDescriptorSet set, VkBuffer args, VkDeviceSize offset,
                           std::span<const std::byte> push = {}) const;

private:
    void destroy() noexcept;

    const Context* ctx_ = nullptr;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::uint32_t push_constant_size_ = 0;
};

}  // namespace fg::vk
