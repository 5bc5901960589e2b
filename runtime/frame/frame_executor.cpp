#include "frame_executor.h"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>
#include <stdexcept>

#include "vk/commands.h"
#include "vk/timestamp_queries.h"

namespace fg {

namespace {

VkDescriptorType descriptor_type(const std::string& kind) {
    if (kind == "uniform_buffer") return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (kind == "storage_buffer") return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (kind == "storage_image") return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
}

VkFormat vk_format(ImageFormat f) {
    switch (f) {
        case ImageFormat::R32F: return VK_FORMAT_R32_SFLOAT;
        case ImageFormat::RG32F: return VK_FORMAT_R32G32_SFLOAT;
        case ImageFormat::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case ImageFormat::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
    }
    return VK_FORMAT_R32_SFLOAT;
}

// Standard resources every pass may bind, by the block names the templates declare.
const char* standard_resource(const std::string& binding) {
    if (binding == "FgFrame") return "frame";
    if (binding == "FgScene") return "scene";
    if (binding == "FgParams") return "params";
    if (binding == "FgCounters") return "counters";
    return nullptr;
}

}  // namespace

vk::SpecializationValues specialization_for(const PackManifest& m, const ManifestPass& pass,
                                            const std::map<std::string, double>& knobs, bool count_evaluations) {
    for (const auto& [name, value] : knobs) {
        const auto* spec = m.find_spec(name);
        if (!spec) {
            std::string names;
            for (const auto& s : m.spec_constants) names += (names.empty() ? "" : ", ") + s.name;
            throw std::runtime_error(fmt::format("unknown knob \"{}\"; this pack's knobs are: {}", name, names));
        }
        if ((spec->min && value < *spec->min) || (spec->max && value > *spec->max))
            throw std::runtime_error(fmt::format("knob {} = {} is outside [{}, {}]", name, value, spec->min.value_or(-1e300),
                                                 spec->max.value_or(1e300)));
        if (spec->type == ValueType::Int && value != static_cast<double>(static_cast<std::int64_t>(value)))
            throw std::runtime_error(fmt::format("knob {} is an integer, not {}", name, value));
    }
    vk::SpecializationValues values;
    for (std::uint32_t id : pass.spec_constants) {
        const auto* spec = m.find_spec(id);
        if (!spec) continue;
        double v = spec->value;
        if (auto it = knobs.find(spec->name); it != knobs.end()) v = it->second;
        if (spec->name == "count_evaluations") v = count_evaluations ? 1.0 : 0.0;
        switch (spec->type) {
            case ValueType::Int: values.set(id, static_cast<std::int32_t>(v)); break;
            case ValueType::Bool: values.set(id, static_cast<std::uint32_t>(v != 0.0 ? 1u : 0u)); break;
            default: values.set(id, static_cast<float>(v)); break;
        }
    }
    return values;
}

FrameExecutor::FrameExecutor(const vk::Context& ctx, const Pack& pack, FrameGraph graph)
    : ctx_(ctx), manifest_(pack.manifest), graph_(std::move(graph)) {
    auto check_block = [&](const char* name, std::size_t size) {
        auto it = manifest_.uniform_blocks.find(name);
        if (it != manifest_.uniform_blocks.end() && it->second != size)
            throw std::runtime_error(fmt::format("the pack's {} block is {} bytes, this runtime writes {}: the pack was "
                                                 "compiled by another version of fgc; recompile it",
                                                 name, it->second, size));
    };
    check_block("FgFrame", sizeof(GpuFrame));
    check_block("FgScene", sizeof(GpuScene));
    // Without shaderFloat64 the pipelines would fail to build or, worse, a driver could run them
    // in float: refuse up front.
    if (manifest_.precision == "double" && !ctx.shader_float64_enabled())
        throw std::runtime_error(fmt::format(
            "the pack '{}' evaluates its scene in double precision (scene.precision \"double\"), and {} has no "
            "shaderFloat64 (or the context was made without it); use a device with 64-bit floats, or recompile "
            "with fgc compile --precision float (deep zooms then lose their structure)",
            manifest_.name, ctx.device_name()));
    make_programs(pack);
    make_resources();
    make_descriptor_sets();
}

FrameExecutor::~FrameExecutor() = default;

void FrameExecutor::make_programs(const Pack& pack) {
    for (const auto& pass : graph_.passes()) {
        if (programs_.count(pass.program)) continue;
        const ManifestPass* mp = manifest_.find_pass(pass.program);
        if (!mp) throw std::runtime_error(fmt::format("the pack has no '{}' pass", pass.program));
        std::vector<vk::DescriptorBinding> bindings;
        for (const auto& b : mp->bindings) {
            if (b.set != 0) throw std::runtime_error(fmt::format("pass {} uses descriptor set {}", mp->name, b.set));
            bindings.push_back({b.binding, descriptor_type(b.kind)});
        }
        Program prog;
        prog.manifest = mp;
        prog.layout = std::make_unique<vk::DescriptorSetLayout>(ctx_, bindings);
        auto spec = specialization_for(manifest_, *mp, graph_.settings.knobs, graph_.settings.count_evaluations);
        prog.pipeline = std::make_unique<vk::ComputePipeline>(ctx_, pack.spirv.at(mp->name),
                                                              std::vector<VkDescriptorSetLayout>{prog.layout->handle()},
                                                              mp->push_constant_size, spec);
        programs_[pass.program] = std::move(prog);
    }
}

void FrameExecutor::make_resources() {
    for (const auto& img : graph_.images())
        images_[img.name] = std::make_unique<vk::StorageImage>(ctx_, vk_format(img.format), VkExtent2D{img.width, img.height});
    for (const auto& b : graph_.buffers())
        buffers_[b.name] = std::make_unique<vk::Buffer>(
            ctx_, b.size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    frame_ = std::make_unique<vk::Buffer>(ctx_, sizeof(GpuFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryKind::HostVisible);
    scene_ = std::make_unique<vk::Buffer>(ctx_, sizeof(GpuScene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryKind::HostVisible);
    params_bytes_.assign(std::max<std::size_t>(16, manifest_.params_size), std::byte{0});
    params_ = std::make_unique<vk::Buffer>(ctx_, params_bytes_.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           vk::MemoryKind::HostVisible);
    for (const auto& p : manifest_.params) set_param(p.name, p.value);
    std::size_t slots = std::max<std::size_t>(1, graph_.counter_groups().size());
    counters_ = std::make_unique<vk::Buffer>(ctx_, slots * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
    set_scene(make_gpu_scene(manifest_.scene));
}

void FrameExecutor::make_descriptor_sets() {
    std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
    for (const auto& pass : graph_.passes())
        for (const auto& b : programs_.at(pass.program).manifest->bindings)
            for (auto& s : sizes)
                if (s.type == descriptor_type(b.kind)) ++s.descriptorCount;
    pool_ = std::make_unique<vk::DescriptorPool>(ctx_, static_cast<std::uint32_t>(graph_.passes().size()), sizes);
    for (const auto& pass : graph_.passes()) {
        const Program& prog = programs_.at(pass.program);
        VkDescriptorSet set = pool_->allocate(*prog.layout);
        for (const auto& b : prog.manifest->bindings) {
            std::string resource;
            for (const auto& [name, res] : pass.bindings)
                if (name == b.name) resource = res;
            if (resource.empty()) {
                const char* std_res = standard_resource(b.name);
                if (!std_res)
                    throw std::runtime_error(fmt::format("pass {} binds '{}' ({}), which this runtime's frame graph "
                                                         "does not provide: recompile the pack with this fgc",
                                                         pass.label, b.name, b.kind));
                resource = std_res;
            }
            if (resource == "frame") vk::write_uniform_buffer(ctx_, set, b.binding, *frame_);
            else if (resource == "scene") vk::write_uniform_buffer(ctx_, set, b.binding, *scene_);
            else if (resource == "params") vk::write_uniform_buffer(ctx_, set, b.binding, *params_);
            else if (resource == "counters") vk::write_storage_buffer(ctx_, set, b.binding, *counters_);
            else if (auto buf = buffers_.find(resource); buf != buffers_.end())
                vk::write_storage_buffer(ctx_, set, b.binding, *buf->second);
            else {
                auto img = images_.find(resource);
                if (img == images_.end())
                    throw std::runtime_error(fmt::format("pass {}: no image '{}'", pass.label, resource));
                vk::write_storage_image(ctx_, set, b.binding, *img->second);
            }
        }
        sets_.push_back(set);
    }
}

void FrameExecutor::set_frame(const GpuFrame& frame) {
    std::memcpy(frame_->data(), &frame, sizeof frame);
    frame_->flush();
}

void FrameExecutor::set_scene(const GpuScene& scene) {
    std::memcpy(scene_->data(), &scene, sizeof scene);
    scene_->flush();
}

bool FrameExecutor::set_param(const std::string& name, const Constant& value) {
    const auto* p = manifest_.find_param(name);
    if (!p) return false;
    for (int i = 0; i < component_count(p->type); ++i) {
        std::byte* at = params_bytes_.data() + p->offset + 4 * static_cast<std::size_t>(i);
        double v = value.v[static_cast<std::size_t>(i)];
        if (p->type == ValueType::Int || p->type == ValueType::Bool) {
            std::int32_t x = static_cast<std::int32_t>(v);
            std::memcpy(at, &x, 4);
        } else {
            float x = static_cast<float>(v);
            std::memcpy(at, &x, 4);
        }
    }
    std::memcpy(params_->data(), params_bytes_.data(), params_bytes_.size());
    params_->flush();
    return true;
}

FrameStats FrameExecutor::run() {
    FrameStats stats;
    std::fill_n(counters_->data(), counters_->size(), std::byte{0});
    counters_->flush();
    bool timing = ctx_.timestamps_supported();
    std::unique_ptr<vk::GpuTimer> timer;
    if (timing) timer = std::make_unique<vk::GpuTimer>(ctx_, static_cast<std::uint32_t>(graph_.passes().size() + 2));
    vk::OneShot shot(ctx_);
    VkCommandBuffer cmd = shot.cmd();
    if (timer) timer->reset(cmd);
    if (!images_initialised_) {
        for (auto& [_, img] : images_)
            img->transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::none, vk::access::compute_read_write);
        images_initialised_ = true;
    }
    for (const auto& b : graph_.buffers())
        if (!b.reset.empty())
            vkCmdUpdateBuffer(cmd, buffers_.at(b.name)->handle(), 0, b.reset.size() * 4, b.reset.data());
    vk::transfer_to_compute_barrier(cmd);
    if (timer) timer->begin(cmd, "frame");
    for (std::size_t i = 0; i < graph_.passes().size(); ++i) {
        const auto& pass = graph_.passes()[i];
        const Program& prog = programs_.at(pass.program);
        if (timer) timer->begin(cmd, pass.timer);
        std::vector<std::byte> push(prog.manifest->push_constant_size, std::byte{0});
        if (!push.empty()) std::memcpy(push.data(), pass.push.data(), std::min(push.size(), pass.push.size() * 4));
        if (pass.indirect.empty())
            prog.pipeline->dispatch(cmd, sets_[i], {pass.groups[0], pass.groups[1], pass.groups[2]}, push);
        else
            prog.pipeline->dispatch_indirect(cmd, sets_[i], buffers_.at(pass.indirect)->handle(), 0, push);
        if (timer) timer->end(cmd, pass.timer);
        // Every pass may read what the one before wrote, also as indirect dispatch sizes.
        vk::memory_barrier(cmd, vk::access::compute_write,
                           {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT});
    }
    if (timer) timer->end(cmd, "frame");
    vk::compute_to_host_barrier(cmd);
    shot.submit_and_wait();
    if (timer) stats.gpu_ms = timer->results();
    counters_->invalidate();
    const auto* counts = reinterpret_cast<const std::uint32_t*>(counters_->data());
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < graph_.counter_groups().size(); ++i) {
        stats.evaluations[graph_.counter_groups()[i]] = counts[i];
        total += counts[i];
    }
    stats.evaluations_per_pixel = static_cast<double>(total) / (2.0 * graph_.width * graph_.height);
    return stats;
}

std::vector<std::byte> FrameExecutor::download(const std::string& image) const {
    auto it = images_.find(image);
    if (it == images_.end()) throw std::runtime_error(fmt::format("the frame graph has no image '{}'", image));
    return it->second->download();
}

}  // namespace fg

namespace fg {

vk::StorageImage& FrameExecutor::image(const std::string& name) const {
    auto it = images_.find(name);
    if (it == images_.end()) throw std::runtime_error(fmt::format("the frame graph has no image '{}'", name));
    return *it->second;
}

}  // namespace fg
