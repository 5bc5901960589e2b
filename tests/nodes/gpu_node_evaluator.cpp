#include "gpu_node_evaluator.h"

#include <algorithm>

#include "codegen/source_map.h"
#include "graph/node_library.h"
#include "node_harness.h"
#include "spirv/glsl_compiler.h"
#include "spirv/spirv_optimizer.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"

namespace fg::test {

namespace {
vk::ContextOptions options() {
    vk::ContextOptions o;
    o.validation = true;
    o.require_timestamps = false;
    return o;
}
}  // namespace

GpuNodeEvaluator::GpuNodeEvaluator() : ctx_(options()) {}

GpuNodeEvaluator& GpuNodeEvaluator::shared() {
    static GpuNodeEvaluator evaluator;
    return evaluator;
}

std::optional<std::vector<CpuValue>> GpuNodeEvaluator::evaluate(const NodeDefinition& def,
                                                                std::optional<ValueType> generic,
                                                                const std::vector<CpuValue>& inputs, std::size_t count,
                                                                Diagnostics& diag) {
    const std::string glsl = evaluation_shader(def, generic, NodeLibrary::builtin().prelude());
    auto spirv = compile_glsl("evaluate " + instance_name(def, generic), glsl, SourceMap{}, diag);
    if (!spirv) return std::nullopt;
    auto optimized = optimize_spirv("evaluate", *spirv, diag);
    if (!optimized || !validate_spirv("evaluate", *optimized, diag)) return std::nullopt;

    const std::size_t nin = std::max<std::size_t>(def.inputs.size(), 1);
    const std::size_t nout = def.outputs.size();
    std::vector<float> in(count * nin * 4, 0.0f);
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (int c = 0; c < 4; ++c) in[i * 4 + static_cast<std::size_t>(c)] = static_cast<float>(inputs[i].v[c]);

    vk::Buffer in_buffer(ctx_, in.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
    in_buffer.upload(in);
    vk::Buffer out_buffer(ctx_, count * nout * 4 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                          vk::MemoryKind::Readback);
    vk::DescriptorSetLayout layout(ctx_, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    vk::DescriptorPool pool(ctx_, layout, 1);
    VkDescriptorSet set = pool.allocate(layout);
    vk::write_storage_buffer(ctx_, set, 0, in_buffer);
    vk::write_storage_buffer(ctx_, set, 1, out_buffer);
    vk::ComputePipeline pipeline(ctx_, *optimized, {layout.handle()}, 4);
    const auto n = static_cast<std::uint32_t>(count);
    vk::OneShot::run(ctx_, [&](VkCommandBuffer cmd) {
        pipeline.dispatch(cmd, set, {vk::groups_for(n, 64)}, vk::bytes_of(n));
        vk::compute_to_host_barrier(cmd);
    });
    auto out = out_buffer.download_as<float>(count * nout * 4);
    std::vector<CpuValue> result(count * nout);
    for (std::size_t i = 0; i < result.size(); ++i)
        for (int c = 0; c < 4; ++c) result[i].v[c] = out[i * 4 + static_cast<std::size_t>(c)];
    return result;
}

}  // namespace fg::test
