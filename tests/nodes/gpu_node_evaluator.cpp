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
    o.shader_float64 = true;   // the double variants of the node tests
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
                                                                Diagnostics& diag, bool in_double) {
    const std::string glsl = evaluation_shader(def, generic, NodeLibrary::builtin().prelude(), in_double);
    return run("evaluate " + instance_name(def, generic), glsl, inputs, count, def.outputs.size(), in_double, diag);
}

namespace {
template <class T>
std::optional<std::vector<CpuValue>> run_as(const vk::Context& ctx, const std::vector<std::uint32_t>& spirv,
                                            const std::vector<CpuValue>& inputs, std::size_t count, std::size_t nout) {
    std::vector<T> in(std::max<std::size_t>(inputs.size(), 1) * 4, T(0));
    for (std::size_t i = 0; i < inputs.size(); ++i)
        for (int c = 0; c < 4; ++c) in[i * 4 + static_cast<std::size_t>(c)] = static_cast<T>(inputs[i].v[c]);
    vk::Buffer in_buffer(ctx, in.size() * sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
    in_buffer.upload(in);
    vk::Buffer out_buffer(ctx, count * nout * 4 * sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                          vk::MemoryKind::Readback);
    vk::DescriptorSetLayout layout(ctx, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    vk::DescriptorPool pool(ctx, layout, 1);
    VkDescriptorSet set = pool.allocate(layout);
    vk::write_storage_buffer(ctx, set, 0, in_buffer);
    vk::write_storage_buffer(ctx, set, 1, out_buffer);
    vk::ComputePipeline pipeline(ctx, spirv, {layout.handle()}, 4);
    const auto n = static_cast<std::uint32_t>(count);
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        pipeline.dispatch(cmd, set, {vk::groups_for(n, 64)}, vk::bytes_of(n));
        vk::compute_to_host_barrier(cmd);
    });
    auto out = out_buffer.download_as<T>(count * nout * 4);
    std::vector<CpuValue> result(count * nout);
    for (std::size_t i = 0; i < result.size(); ++i)
        for (int c = 0; c < 4; ++c) result[i].v[c] = static_cast<double>(out[i * 4 + static_cast<std::size_t>(c)]);
    return result;
}
}  // namespace

std::optional<std::vector<CpuValue>> GpuNodeEvaluator::run(const std::string& name, const std::string& glsl,
                                                           const std::vector<CpuValue>& inputs, std::size_t count,
                                                           std::size_t nout, bool in_double, Diagnostics& diag) {
    if (in_double && !ctx_.shader_float64_enabled()) {
        diag.error(ctx_.device_name() + " has no shaderFloat64");
        return std::nullopt;
    }
    auto spirv = compile_glsl(name, glsl, SourceMap{}, diag);
    if (!spirv) return std::nullopt;
    auto optimized = optimize_spirv(name, *spirv, diag);
    if (!optimized || !validate_spirv(name, *optimized, diag)) return std::nullopt;
    if (in_double) return run_as<double>(ctx_, *optimized, inputs, count, nout);
    return run_as<float>(ctx_, *optimized, inputs, count, nout);
}

}  // namespace fg::test
