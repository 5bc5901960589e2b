#include "frame/pipeline_store.h"

#include <bit>

#include <xxhash.h>

namespace fg {

namespace {

std::uint64_t pipeline_key(std::span<const std::uint32_t> spirv, const std::vector<vk::DescriptorBinding>& bindings,
                           std::uint32_t push_constant_size, const vk::SpecializationValues& specialization) {
    std::vector<std::uint32_t> words(spirv.begin(), spirv.end());
    words.push_back(push_constant_size);
    for (const auto& b : bindings)
        words.insert(words.end(), {b.binding, static_cast<std::uint32_t>(b.type), b.stages, b.count});
    for (const auto& v : specialization.values) {
        words.push_back(v.id);
        words.push_back(static_cast<std::uint32_t>(v.value.index()));
        words.push_back(std::visit([](auto x) { return std::bit_cast<std::uint32_t>(x); }, v.value));
    }
    return XXH3_64bits(words.data(), words.size() * sizeof(std::uint32_t));
}

}  // namespace

std::shared_ptr<const KeptPipeline> build_pipeline(const vk::Context& ctx, std::span<const std::uint32_t> spirv,
                                                   const std::vector<vk::DescriptorBinding>& bindings,
                                                   std::uint32_t push_constant_size,
                                                   const vk::SpecializationValues& specialization) {
    vk::DescriptorSetLayout layout(ctx, bindings);
    vk::ComputePipeline pipeline(ctx, spirv, {layout.handle()}, push_constant_size, specialization);
    return std::make_shared<const KeptPipeline>(KeptPipeline{std::move(layout), std::move(pipeline)});
}

std::shared_ptr<const KeptPipeline> PipelineStore::get(const vk::Context& ctx, std::span<const std::uint32_t> spirv,
                                                       const std::vector<vk::DescriptorBinding>& bindings,
                                                       std::uint32_t push_constant_size,
                                                       const vk::SpecializationValues& specialization) {
    const std::uint64_t key = pipeline_key(spirv, bindings, push_constant_size, specialization);
    {
        std::lock_guard lock(mutex_);
        if (auto it = kept_.find(key); it != kept_.end()) return it->second;
    }
    // Built outside the lock: another scene's pipelines need not wait for this one.
    auto built = build_pipeline(ctx, spirv, bindings, push_constant_size, specialization);
    std::lock_guard lock(mutex_);
    ++built_;
    if (kept_.emplace(key, built).second) order_.push_back(key);
    while (kept_.size() > capacity_) {
        kept_.erase(order_.front());
        order_.pop_front();
    }
    return built;
}

std::uint64_t PipelineStore::built() const {
    std::lock_guard lock(mutex_);
    return built_;
}

}  // namespace fg
