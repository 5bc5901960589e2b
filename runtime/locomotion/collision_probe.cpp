#include "locomotion/collision_probe.h"

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "vk/commands.h"
#include "vk/vulkan_error.h"

namespace fg {

namespace {

// The params block as the shaders read it: each param's default at its std140 offset.
std::vector<std::byte> params_block(const PackManifest& m) {
    std::vector<std::byte> bytes(std::max<std::size_t>(16, m.params_size), std::byte{0});
    for (const auto& p : m.params)
        for (int i = 0; i < component_count(p.type); ++i) {
            std::byte* at = bytes.data() + p.offset + 4 * static_cast<std::size_t>(i);
            double v = p.value.v[static_cast<std::size_t>(i)];
            if (p.type == ValueType::Int || p.type == ValueType::Bool) {
                auto x = static_cast<std::int32_t>(v);
                std::memcpy(at, &x, 4);
            } else {
                auto x = static_cast<float>(v);
                std::memcpy(at, &x, 4);
            }
        }
    return bytes;
}

}  // namespace

CollisionProbe::CollisionProbe(const vk::Context& ctx, const Pack& pack, PipelineStore* pipelines) : ctx_(ctx) {
    const ManifestPass* pass = pack.manifest.find_pass("probe");
    if (!pass) throw std::runtime_error("the pack has no probe pass: recompile it with this fgc");
    std::vector<vk::DescriptorBinding> bindings;
    std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 0}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 0}};
    for (const auto& b : pass->bindings) {
        bool uniform = b.kind == "uniform_buffer";
        bindings.push_back({b.binding, uniform ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
        sizes[uniform ? 0 : 1].descriptorCount += static_cast<std::uint32_t>(kSlots);
    }
    std::erase_if(sizes, [](const VkDescriptorPoolSize& s) { return s.descriptorCount == 0; });
    const auto& spirv = pack.spirv.at("probe");
    const auto spec = specialization_for(pack.manifest, *pass, {}, false);
    kept_ = pipelines ? pipelines->get(ctx, spirv, bindings, pass->push_constant_size, spec)
                      : build_pipeline(ctx, spirv, bindings, pass->push_constant_size, spec);
    if (pass->push_constant_size != sizeof(ProbePush))
        throw std::runtime_error(fmt::format("the pack's probe pass takes {} bytes of push constants, this runtime pushes {}: "
                                             "recompile the pack with this fgc",
                                             pass->push_constant_size, sizeof(ProbePush)));
    pool_ = std::make_unique<vk::DescriptorPool>(ctx, static_cast<std::uint32_t>(kSlots), sizes);

    auto uniform = [&](std::size_t size) {
        return std::make_unique<vk::Buffer>(ctx, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryKind::HostVisible);
    };
    GpuScene scene = make_gpu_scene(pack.manifest.scene);
    std::vector<std::byte> params = params_block(pack.manifest);
    scene_ = uniform(sizeof scene);
    params_ = uniform(params.size());
    std::memcpy(scene_->data(), &scene, sizeof scene);
    std::memcpy(params_->data(), params.data(), params.size());
    camera_relative_ = pack.manifest.precision == "double";
    scene_->flush();
    params_->flush();
    // Normals from differences a little finer than the scene's size.
    normal_step_ = std::max(1e-5, 1e-4 * static_cast<double>(scene.bounds_radius));
    // A double pack's taps are float offsets from an anchor at the probe: no 1e-5 floor, so a deep
    // zoom's bounds (2e-5 across) get normals on their own scale.
    if (camera_relative_) normal_step_ = 1e-4 * static_cast<double>(scene.bounds_radius);

    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = ctx.queue_family();
    vk::check(vkCreateCommandPool(ctx.device(), &pi, nullptr, &command_pool_), "vkCreateCommandPool");
    for (auto& slot : slots_) {
        slot.points = std::make_unique<vk::Buffer>(ctx, kMaxPoints * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
        slot.results = std::make_unique<vk::Buffer>(ctx, kMaxPoints * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
        GpuFrame frame{};
        slot.frame = uniform(sizeof frame);
        std::memcpy(slot.frame->data(), &frame, sizeof frame);
        slot.frame->flush();
        VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        ai.commandPool = command_pool_;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        vk::check(vkAllocateCommandBuffers(ctx.device(), &ai, &slot.cmd), "vkAllocateCommandBuffers");
        VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        vk::check(vkCreateFence(ctx.device(), &fi, nullptr, &slot.fence), "vkCreateFence");
        slot.set = pool_->allocate(kept_->layout);
        for (const auto& b : pass->bindings) {
            if (b.name == "FgFrame") vk::write_uniform_buffer(ctx, slot.set, b.binding, *slot.frame);
            else if (b.name == "FgScene") vk::write_uniform_buffer(ctx, slot.set, b.binding, *scene_);
            else if (b.name == "FgParams") vk::write_uniform_buffer(ctx, slot.set, b.binding, *params_);
            else if (b.name == "FgProbePoints") vk::write_storage_buffer(ctx, slot.set, b.binding, *slot.points);
            else if (b.name == "FgProbeResults") vk::write_storage_buffer(ctx, slot.set, b.binding, *slot.results);
            else throw std::runtime_error(fmt::format("the probe pass binds '{}', which this runtime does not provide", b.name));
        }
    }
}

CollisionProbe::~CollisionProbe() {
    for (auto& slot : slots_)
        if (slot.fence) {
            if (slot.ticket) vkWaitForFences(ctx_.device(), 1, &slot.fence, VK_TRUE, UINT64_MAX);
            vkDestroyFence(ctx_.device(), slot.fence, nullptr);
        }
    if (command_pool_) vkDestroyCommandPool(ctx_.device(), command_pool_, nullptr);
}

std::uint64_t CollisionProbe::submit(const std::vector<glm::dvec3>& points) {
    Slot* free = nullptr;
    for (auto& s : slots_)
        if (s.ticket == 0) free = &s;
    if (!free || points.empty()) return 0;
    std::size_t n = std::min(points.size(), kMaxPoints);
    glm::dvec3 anchor(0.0);
    if (camera_relative_) {
        anchor = points[0];
        GpuFrame frame{};
        const glm::dvec3 hi = glm::dvec3(glm::vec3(anchor));
        const glm::dvec3 lo = anchor - hi;
        frame.anchor_hi = {static_cast<float>(hi.x), static_cast<float>(hi.y), static_cast<float>(hi.z), 0.0f};
        frame.anchor_lo = {static_cast<float>(lo.x), static_cast<float>(lo.y), static_cast<float>(lo.z), 0.0f};
        std::memcpy(free->frame->data(), &frame, sizeof frame);
        free->frame->flush();
    }
    auto* p = reinterpret_cast<float*>(free->points->data());
    for (std::size_t i = 0; i < n; ++i) {
        p[4 * i + 0] = static_cast<float>(points[i].x - anchor.x);
        p[4 * i + 1] = static_cast<float>(points[i].y - anchor.y);
        p[4 * i + 2] = static_cast<float>(points[i].z - anchor.z);
        p[4 * i + 3] = 0.0f;
    }
    free->points->flush();
    free->asked.assign(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(n));

    vk::check(vkResetCommandBuffer(free->cmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(free->cmd, &bi), "vkBeginCommandBuffer");
    vk::memory_barrier(free->cmd, vk::access::host_write, vk::access::compute_read);
    const ProbePush push{static_cast<std::int32_t>(n), static_cast<float>(normal_step_)};
    kept_->pipeline.dispatch(free->cmd, free->set, {1, 1, 1},
                        std::span<const std::byte>(reinterpret_cast<const std::byte*>(&push), sizeof push));
    vk::compute_to_host_barrier(free->cmd);
    vk::check(vkEndCommandBuffer(free->cmd), "vkEndCommandBuffer");
    ctx_.submit(free->cmd, free->fence);
    free->ticket = next_ticket_++;
    return free->ticket;
}

ProbeResult CollisionProbe::collect(Slot& slot) {
    vk::check(vkResetFences(ctx_.device(), 1, &slot.fence), "vkResetFences");
    slot.results->invalidate();
    const auto* r = reinterpret_cast<const float*>(slot.results->data());
    ProbeResult out;
    out.ticket = slot.ticket;
    for (std::size_t i = 0; i < slot.asked.size(); ++i) {
        ProbeSample s;
        s.point = slot.asked[i];
        s.distance = r[4 * i];
        s.normal = {r[4 * i + 1], r[4 * i + 2], r[4 * i + 3]};
        out.samples.push_back(s);
    }
    slot.ticket = 0;
    return out;
}

std::optional<ProbeResult> CollisionProbe::poll() {
    Slot* newest = nullptr;
    for (auto& s : slots_)
        if (s.ticket && vkGetFenceStatus(ctx_.device(), s.fence) == VK_SUCCESS && (!newest || s.ticket > newest->ticket))
            newest = &s;
    if (!newest) return std::nullopt;
    // Older finished probes are superseded: free their slots too.
    std::optional<ProbeResult> out = collect(*newest);
    for (auto& s : slots_)
        if (s.ticket && s.ticket < out->ticket && vkGetFenceStatus(ctx_.device(), s.fence) == VK_SUCCESS) collect(s);
    return out;
}

std::optional<ProbeResult> CollisionProbe::wait(std::uint64_t ticket) {
    for (auto& s : slots_)
        if (s.ticket == ticket && ticket != 0) {
            vk::check(vkWaitForFences(ctx_.device(), 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
            return collect(s);
        }
    return std::nullopt;
}

}  // namespace fg
