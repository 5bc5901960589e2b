#pragma once
// Compute pipelines kept by everything that decides them: the SPIR-V, the descriptor bindings, the
// push-constant size and the specialization values. A scene rebuilt after an edit takes the
// pipelines of the passes the edit did not change from here instead of building them again (a
// VkPipelineCache would do that on drivers that fill one; lavapipe in Mesa 22 keeps nothing in it).
// Shared by the threads that build scenes.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"

namespace fg {

struct KeptPipeline {
    vk::DescriptorSetLayout layout;
    vk::ComputePipeline pipeline;
};

// One pipeline with its set layout, built now.
std::shared_ptr<const KeptPipeline> build_pipeline(const vk::Context& ctx, std::span<const std::uint32_t> spirv,
                                                   const std::vector<vk::DescriptorBinding>& bindings,
                                                   std::uint32_t push_constant_size,
                                                   const vk::SpecializationValues& specialization);

class PipelineStore {
public:
    explicit PipelineStore(std::size_t capacity = 64) : capacity_(capacity) {}

    // The kept pipeline for these inputs, or a new one (kept; the oldest makes room when full).
    std::shared_ptr<const KeptPipeline> get(const vk::Context& ctx, std::span<const std::uint32_t> spirv,
                                            const std::vector<vk::DescriptorBinding>& bindings,
                                            std::uint32_t push_constant_size,
                                            const vk::SpecializationValues& specialization);
    // Pipelines built so far (the others were reused).
    std::uint64_t built() const;

private:
    mutable std::mutex mutex_;
    std::size_t capacity_;
    std::map<std::uint64_t, std::shared_ptr<const KeptPipeline>> kept_;
    std::deque<std::uint64_t> order_;   // oldest first
    std::uint64_t built_ = 0;
};

}  // namespace fg
