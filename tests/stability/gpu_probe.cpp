#include "gpu_probe.h"

#include <cstring>
#include <stdexcept>

#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "vk/buffer.h"
#include "vk/commands.h"
#include "vk/compute_pipeline.h"
#include "vk/descriptors.h"

namespace fg::test {

std::vector<glm::vec4> gpu_probe(const vk::Context& ctx, const Pack& pack, const std::vector<glm::dvec3>& points,
                                 float normal_step, glm::dvec3 anchor) {
    if (pack.manifest.precision != "double") anchor = glm::dvec3(0.0);
    const ManifestPass* pass = pack.manifest.find_pass("probe");
    if (!pass) throw std::runtime_error("the pack has no probe pass");
    std::vector<vk::DescriptorBinding> bindings;
    for (const auto& b : pass->bindings)
        bindings.push_back({b.binding, b.kind == "uniform_buffer" ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
    vk::DescriptorSetLayout layout(ctx, bindings);
    vk::ComputePipeline pipeline(ctx, pack.spirv.at(pass->name), {layout.handle()}, pass->push_constant_size,
                                 specialization_for(pack.manifest, *pass, {}, false));
    const std::size_t n = points.size();
    auto host = [&](VkDeviceSize size, VkBufferUsageFlags usage) {
        return std::make_unique<vk::Buffer>(ctx, size, usage, vk::MemoryKind::HostVisible);
    };
    auto frame = host(sizeof(GpuFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    auto scene = host(sizeof(GpuScene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    auto params = host(std::max<std::size_t>(16, pack.manifest.params_size), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    auto in = host(16 * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    auto out = host(16 * n, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    GpuFrame f{};
    const glm::dvec3 hi = glm::dvec3(glm::vec3(anchor)), lo = anchor - hi;
    f.anchor_hi = {static_cast<float>(hi.x), static_cast<float>(hi.y), static_cast<float>(hi.z), 0.0f};
    f.anchor_lo = {static_cast<float>(lo.x), static_cast<float>(lo.y), static_cast<float>(lo.z), 0.0f};
    std::memcpy(frame->data(), &f, sizeof f);
    GpuScene s = make_gpu_scene(pack.manifest.scene);
    std::memcpy(scene->data(), &s, sizeof s);
    std::memset(params->data(), 0, params->size());
    for (const auto& p : pack.manifest.params)
        for (int i = 0; i < component_count(p.type); ++i) {
            std::byte* at = params->data() + p.offset + 4 * static_cast<std::size_t>(i);
            double v = p.value.v[static_cast<std::size_t>(i)];
            if (p.type == ValueType::Int || p.type == ValueType::Bool) {
                std::int32_t x = static_cast<std::int32_t>(v);
                std::memcpy(at, &x, 4);
            } else {
                float x = static_cast<float>(v);
                std::memcpy(at, &x, 4);
            }
        }
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec4 v(glm::vec3(points[i] - anchor), 1.0f);
        std::memcpy(in->data() + 16 * i, &v, 16);
    }
    for (auto* b : {frame.get(), scene.get(), params.get(), in.get()}) b->flush();
    std::vector<VkDescriptorPoolSize> sizes{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 3}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}};
    vk::DescriptorPool pool(ctx, 1, sizes);
    VkDescriptorSet set = pool.allocate(layout);
    for (const auto& b : pass->bindings) {
        if (b.name == "FgFrame") vk::write_uniform_buffer(ctx, set, b.binding, *frame);
        else if (b.name == "FgScene") vk::write_uniform_buffer(ctx, set, b.binding, *scene);
        else if (b.name == "FgParams") vk::write_uniform_buffer(ctx, set, b.binding, *params);
        else if (b.name == "FgProbePoints") vk::write_storage_buffer(ctx, set, b.binding, *in);
        else if (b.name == "FgProbeResults") vk::write_storage_buffer(ctx, set, b.binding, *out);
        else throw std::runtime_error("probe pass binds unknown " + b.name);
    }
    const ProbePush push{static_cast<std::int32_t>(n), normal_step};
    vk::OneShot::run(ctx, [&](VkCommandBuffer cmd) {
        pipeline.dispatch(cmd, set, {static_cast<std::uint32_t>((n + 63) / 64), 1, 1},
                          std::span<const std::byte>(reinterpret_cast<const std::byte*>(&push), sizeof push));
        vk::compute_to_host_barrier(cmd);
    });
    out->invalidate();
    std::vector<glm::vec4> results(n);
    std::memcpy(results.data(), out->data(), 16 * n);
    return results;
}

}  // namespace fg::test
