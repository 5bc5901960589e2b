#include "frame_executor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <stdexcept>

#include "common/spec_constants.h"
#include "environment_light.h"
#include "persistent_groups.h"
#include "sample_jitter.h"
#include "vk/commands.h"
#include "vk/timestamp_queries.h"

namespace fg {

namespace {

// The frustum edges of a view without its jitter (stereo_rig.h: jittered()).
glm::vec4 unjittered_fov(const GpuView& v, glm::vec2 jitter, glm::uvec2 size) {
    const float dx = jitter.x * (v.tan_fov.y - v.tan_fov.x) / static_cast<float>(size.x);
    const float dy = jitter.y * (v.tan_fov.w - v.tan_fov.z) / static_cast<float>(size.y);
    return {v.tan_fov.x - dx, v.tan_fov.y - dx, v.tan_fov.z + dy, v.tan_fov.w + dy};
}

// Whether both eyes of `frame` look from where and where `previous` (jittered by
// `previous_jitter`) looked: a still head, whatever the jitter.
bool same_view_unjittered(const GpuFrame& frame, const GpuView (&previous)[2], glm::vec2 previous_jitter) {
    const glm::vec2 jitter(frame.jitter.x, frame.jitter.y);
    for (int eye = 0; eye < 2; ++eye) {
        const GpuView &a = frame.views[eye], &b = previous[eye];
        if (a.origin != b.origin || a.right != b.right || a.up != b.up || a.forward != b.forward) return false;
        const glm::vec4 fa = unjittered_fov(a, jitter, frame.eye_size), fb = unjittered_fov(b, previous_jitter, frame.eye_size);
        const float tolerance = 1e-5f * (std::abs(fa.y - fa.x) + std::abs(fa.w - fa.z));
        if (glm::any(glm::greaterThan(glm::abs(fa - fb), glm::vec4(tolerance)))) return false;
    }
    return true;
}

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
        case ImageFormat::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case ImageFormat::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
        case ImageFormat::RGBA32UI: return VK_FORMAT_R32G32B32A32_UINT;
    }
    return VK_FORMAT_R32_SFLOAT;
}

// The executor's stand-in for a binding a pass leaves unused: a 1x1 image of the shader's declared
// format, or a small buffer, of that pass and binding alone (passes of one batch run without
// barriers between them, so they share no stand-in). Not the frame graph's: it declares nothing.
std::string stand_in_name(const FramePass& pass, const ManifestBinding& b) { return "stand_in." + pass.label + "." + b.name; }

ImageFormat image_format_named(const std::string& name) {
    for (ImageFormat f : {ImageFormat::R32F, ImageFormat::RG32F, ImageFormat::RGBA16F, ImageFormat::RGBA32F,
                          ImageFormat::RGBA8, ImageFormat::RGBA32UI})
        if (name == image_format_name(f)) return f;
    throw std::runtime_error(fmt::format("a storage image of format '{}', which this runtime does not make: recompile "
                                         "the pack with this fgc", name));
}

// Standard resources every pass may bind, by the block names the templates declare.
const char* standard_resource(const std::string& binding) {
    if (binding == "FgFrame") return "frame";
    if (binding == "FgScene") return "scene";
    if (binding == "FgParams") return "params";
    if (binding == "FgCounters") return "counters";
    if (binding == "FgTiles") return "no_tiles";
    if (binding == "FgEnvironment") return "environment";
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

// The pipeline a pass runs: its program, specialized by the dispatch constants it fixes.
std::string FrameExecutor::program_key(const FramePass& pass) {
    std::string key = pass.program;
    for (const auto& [id, value] : pass.specialize) key += fmt::format(" {}={}", id, value);
    return key;
}

FrameExecutor::FrameExecutor(const vk::Context& ctx, const Pack& pack, FrameGraph graph, PipelineStore* pipelines,
                             SharedTaaHistory* taa_history)
    : ctx_(ctx), manifest_(pack.manifest), graph_(std::move(graph)), batches_(graph_.batches()) {
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
    make_programs(pack, pipelines);
    check_declarations();
    make_resources(taa_history);
    if (manifest_.effects.has(Effect::Environment)) {
        const auto words = environment_words(pack.environment ? *pack.environment : uniform_environment());
        environment_ = std::make_unique<vk::Buffer>(ctx_, words.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                    vk::MemoryKind::DeviceLocal);
        environment_->upload(words);
    }
    make_descriptor_sets();
}

FrameExecutor::~FrameExecutor() = default;

void FrameExecutor::make_programs(const Pack& pack, PipelineStore* pipelines) {
    for (const auto& pass : graph_.passes()) {
        std::string key = program_key(pass);
        if (programs_.count(key)) continue;
        const ManifestPass* mp = manifest_.find_pass(pass.program);
        if (!mp) throw std::runtime_error(fmt::format("the pack has no '{}' pass", pass.program));
        std::vector<vk::DescriptorBinding> bindings;
        for (const auto& b : mp->bindings) {
            if (b.set != 0) throw std::runtime_error(fmt::format("pass {} uses descriptor set {}", mp->name, b.set));
            bindings.push_back({b.binding, descriptor_type(b.kind)});
        }
        Program prog;
        prog.manifest = mp;
        auto spec = specialization_for(manifest_, *mp, graph_.settings.knobs, graph_.settings.count_evaluations);
        for (std::uint32_t id : mp->dispatch_constants) {
            if (id == kSpecProjection.id) spec.set(id, static_cast<std::int32_t>(graph_.settings.projection));
            if (id == kSpecLens.id) spec.set(id, graph_.settings.frames_may_hold_lens() ? 1 : 0);
            if (id == kSpecFoveated.id) spec.set(id, graph_.settings.foveation > 0.0 ? 1 : 0);
            if (auto it = pass.specialize.find(id); it != pass.specialize.end()) spec.set(id, it->second);
        }
        const auto& spirv = pack.spirv.at(mp->name);
        prog.kept = pipelines ? pipelines->get(ctx_, spirv, bindings, mp->push_constant_size, spec)
                              : build_pipeline(ctx_, spirv, bindings, mp->push_constant_size, spec);
        programs_[key] = std::move(prog);
    }
    for (const auto& pass : graph_.passes()) pass_programs_.push_back(&programs_.at(program_key(pass)));
}

// The declarations drive the barriers, so they must say what the shaders do: every resource a
// shader reads is declared read (or written), every one it writes is declared written, and the push
// constants are exactly the shader's block.
void FrameExecutor::check_declarations() const {
    for (std::size_t i = 0; i < graph_.passes().size(); ++i) {
        const FramePass& pass = graph_.passes()[i];
        const ManifestPass& mp = *pass_programs_[i]->manifest;
        if (pass.push.size() != mp.push_constant_size)
            throw std::runtime_error(fmt::format("pass {} pushes {} bytes of constants, and its shader's block is {} bytes: "
                                                 "the runtime and the pack disagree (recompile the pack with this fgc)",
                                                 pass.label, pass.push.size(), mp.push_constant_size));
        // fg_dispatch_cell places one 8x8 workgroup on each tile.
        if (pass.specialize.count(kSpecTileList.id) && (mp.local_size[0] != 8 || mp.local_size[1] != 8))
            throw std::runtime_error(fmt::format("pass {} dispatches tiles with {}x{} workgroups: its shader needs 8x8",
                                                 pass.label, mp.local_size[0], mp.local_size[1]));
        for (const auto& b : mp.bindings) {
            std::string resource;
            for (const auto& [name, res] : pass.bindings)
                if (name == b.name) resource = res;
            if (resource.empty()) continue;   // a standard resource, or missing: make_descriptor_sets says which
            bool read = pass.reads_resource(resource), written = pass.writes_resource(resource);
            const char* problem = nullptr;
            if (b.access == "read" && !read && !written) problem = "reads";
            if (b.access == "write" && !written) problem = "writes";
            if (b.access == "read_write" && !read && !written) problem = "uses";
            if (problem)
                throw std::runtime_error(fmt::format("pass {} binds {} to '{}', which its shader {}, but the pass does not "
                                                     "declare it: its barriers would be wrong",
                                                     pass.label, resource, b.name, problem));
            const FrameImage* image = b.kind == "storage_image" ? graph_.find_image(current(resource)) : nullptr;
            if (image && b.format.empty())
                throw std::runtime_error(fmt::format("pass {}: the pack does not record its images' formats, so it was "
                                                     "compiled by an older fgc; recompile it from its graph with this fgc",
                                                     pass.label));
            if (image && b.format != image_format_name(image->format))
                throw std::runtime_error(fmt::format("pass {} binds {} ({}) to '{}', which its shader declares {}: "
                                                     "recompile the pack from its graph with this fgc",
                                                     pass.label, resource, image_format_name(image->format), b.name, b.format));
        }
        for (const auto& r : pass.reads)
            if (!graph_.find_image(current(r)) && !graph_.find_buffer(r))
                throw std::runtime_error(fmt::format("pass {} reads {}, which the frame graph does not have", pass.label, r));
    }
}

void FrameExecutor::make_resources(SharedTaaHistory* taa_history) {
    const std::vector<std::string> shared = taa_history ? taa_history_images(graph_) : std::vector<std::string>{};
    for (const auto& img : graph_.images()) {
        auto& versions = images_[img.name];
        const bool shares = std::find(shared.begin(), shared.end(), img.name) != shared.end();
        if (shares) {
            auto it = taa_history->images.find(img.name);
            if (it != taa_history->images.end() && it->second.front()->format() == vk_format(img.format) &&
                it->second.front()->extent().width == img.width && it->second.front()->extent().height == img.height) {
                versions = it->second;
                adopted_.push_back(img.name);
                frames_to_fill_ = std::max<std::uint64_t>(frames_to_fill_, versions.size());
                continue;
            }
        }
        for (int i = 0; i < (img.history ? 2 : 1); ++i)
            versions.push_back(std::make_unique<vk::StorageImage>(ctx_, vk_format(img.format), VkExtent2D{img.width, img.height}));
        if (shares) taa_history->images[img.name] = versions;
        frames_to_fill_ = std::max<std::uint64_t>(frames_to_fill_, versions.size());
    }
    for (const auto& b : graph_.buffers())
        buffers_[b.name] = std::make_unique<vk::Buffer>(
            ctx_, b.size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    // The stand-ins for bindings passes leave unused (FramePass::leave_unused); their code is
    // compiled out, so nothing touches them.
    for (std::size_t i = 0; i < graph_.passes().size(); ++i)
        for (const auto& b : pass_programs_[i]->manifest->bindings) {
            if (!graph_.passes()[i].leaves_unused(b.name)) continue;
            const std::string name = stand_in_name(graph_.passes()[i], b);
            if (b.kind == "storage_image" && !images_.count(name))
                images_[name].push_back(std::make_unique<vk::StorageImage>(ctx_, vk_format(image_format_named(b.format)), VkExtent2D{1, 1}));
            if (b.kind == "storage_buffer" && !buffers_.count(name))
                buffers_[name] = std::make_unique<vk::Buffer>(ctx_, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
        }
    no_tiles_ = std::make_unique<vk::Buffer>(ctx_, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::DeviceLocal);
    frame_ = std::make_unique<vk::Buffer>(ctx_, sizeof(GpuFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryKind::HostVisible);
    scene_ = std::make_unique<vk::Buffer>(ctx_, sizeof(GpuScene), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryKind::HostVisible);
    params_bytes_.assign(std::max<std::size_t>(16, manifest_.params_size), std::byte{0});
    params_ = std::make_unique<vk::Buffer>(ctx_, params_bytes_.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           vk::MemoryKind::HostVisible);
    for (const auto& p : manifest_.params) set_param(p.name, p.value);
    std::size_t slots = std::max<std::size_t>(1, graph_.counter_groups().size());
    counters_ = std::make_unique<vk::Buffer>(ctx_, slots * FG_COUNTER_WORDS * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::HostVisible);
    set_scene(make_gpu_scene(manifest_.scene));
}

vk::StorageImage* FrameExecutor::resolve_image(const std::string& name, std::uint64_t frame) const {
    const std::string image = current(name);
    const bool prev = image != name;
    auto it = images_.find(image);
    if (it == images_.end()) return nullptr;
    const auto& versions = it->second;
    if (versions.size() == 1) return prev ? nullptr : versions[0].get();
    // History images alternate: frame n writes version n % 2 and reads the other as its previous.
    return versions[(frame + (prev ? 1 : 0)) % 2].get();
}

vk::Buffer* FrameExecutor::resolve_buffer(const std::string& name) const {
    if (name == "frame") return frame_.get();
    if (name == "scene") return scene_.get();
    if (name == "params") return params_.get();
    if (name == "counters") return counters_.get();
    if (name == "no_tiles") return no_tiles_.get();
    if (name == "environment") return environment_.get();
    auto it = buffers_.find(name);
    return it == buffers_.end() ? nullptr : it->second.get();
}

void FrameExecutor::make_descriptor_sets() {
    std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
    for (const Program* prog : pass_programs_)
        for (const auto& b : prog->manifest->bindings)
            for (auto& s : sizes)
                if (s.type == descriptor_type(b.kind)) s.descriptorCount += 2;
    pool_ = std::make_unique<vk::DescriptorPool>(ctx_, static_cast<std::uint32_t>(2 * graph_.passes().size()), sizes);
    for (std::size_t i = 0; i < graph_.passes().size(); ++i) {
        const FramePass& pass = graph_.passes()[i];
        const Program& prog = *pass_programs_[i];
        std::array<VkDescriptorSet, 2> sets{};
        for (std::uint64_t parity = 0; parity < 2; ++parity) {
            VkDescriptorSet set = sets[parity] = pool_->allocate(prog.kept->layout);
            for (const auto& b : prog.manifest->bindings) {
                std::string resource;
                for (const auto& [name, res] : pass.bindings)
                    if (name == b.name) resource = res;
                if (resource.empty() && pass.leaves_unused(b.name)) resource = stand_in_name(pass, b);
                if (resource.empty()) {
                    const char* std_res = standard_resource(b.name);
                    if (!std_res)
                        throw std::runtime_error(fmt::format("pass {} binds '{}' ({}), which this runtime's frame graph "
                                                             "does not provide: recompile the pack with this fgc",
                                                             pass.label, b.name, b.kind));
                    resource = std_res;
                }
                if (b.kind == "uniform_buffer" || b.kind == "storage_buffer") {
                    vk::Buffer* buf = resolve_buffer(resource);
                    if (!buf) throw std::runtime_error(fmt::format("pass {}: no buffer '{}'", pass.label, resource));
                    if (b.kind == "uniform_buffer") vk::write_uniform_buffer(ctx_, set, b.binding, *buf);
                    else vk::write_storage_buffer(ctx_, set, b.binding, *buf);
                } else {
                    vk::StorageImage* img = resolve_image(resource, parity);
                    if (!img) throw std::runtime_error(fmt::format("pass {}: no image '{}'", pass.label, resource));
                    vk::write_storage_image(ctx_, set, b.binding, *img);
                }
            }
        }
        sets_.push_back(sets);
    }
}

glm::dvec2 FrameExecutor::taa_jitter() const {
    return graph_.taa ? fg::taa_jitter(history_frames(), graph_.settings.taa_upscale()) : glm::dvec2(0.0);
}

std::uint32_t FrameExecutor::refined_frames() const { return taa_phases(graph_.settings.taa_upscale()); }

void FrameExecutor::set_frame(const GpuFrame& frame) {
    // The pipelines were specialized for the graph's projection (kSpecProjection).
    if (frame.projection != static_cast<std::uint32_t>(graph_.settings.projection))
        throw std::logic_error(fmt::format("a frame in projection {} for pipelines made for projection {}: build the "
                                           "executor for the projection it renders",
                                           frame.projection, static_cast<int>(graph_.settings.projection)));
    // ... and for whether frames hold a lens or a fovea at all (kSpecLens, kSpecFoveated): one they
    // were made without would be ignored.
    const bool lens = frame.views[FG_VIEW_LEFT].lens_radii.x > 0.0f || frame.views[FG_VIEW_RIGHT].lens_radii.x > 0.0f;
    if (lens && !graph_.settings.frames_may_hold_lens())
        throw std::logic_error("a frame with a lens for pipelines made without one: set FrameSettings::lens_mask or headset_lens");
    if ((frame.fovea_radius > 0.0f) != (graph_.settings.foveation > 0.0))
        throw std::logic_error(frame.fovea_radius > 0.0f ? "a foveated frame for a frame graph built without foveation"
                                                         : "a frame without foveation for a foveated frame graph (make the "
                                                           "frame from the graph's settings: they resolve the scene's foveation)");
    frame_data_ = frame;
    frame_data_.previous[0] = previous_views_[0];
    frame_data_.previous[1] = previous_views_[1];
    frame_data_.reuse = graph_.reuse && history_valid_ ? 1u : 0u;
    frame_data_.shade_history = graph_.shade_history && history_valid_ ? 1u : 0u;
    frame_data_.taa_history = graph_.taa && (history_valid_ || taa_taken_) ? 1u : 0u;
    frame_data_.still_frames = 0u;
    if (frame_data_.taa_history && same_view_unjittered(frame_data_, previous_views_, previous_jitter_)) {
        frame_data_.still_frames = still_frames_ + 1;
    }
    frame_data_.jitter.z = previous_jitter_.x;
    frame_data_.jitter.w = previous_jitter_.y;
    std::memcpy(frame_->data(), &frame_data_, sizeof frame_data_);
    frame_->flush();
    update_tile_lists();
}

// The frame set already (or none yet) must not read the previous frame's levels or shading. Not
// through set_frame: before the first frame the uniforms hold no frame to check.
void FrameExecutor::forget_history() {
    history_valid_ = false;
    taa_taken_ = false;
    history_copies_.clear();
    frame_data_.reuse = 0u;
    frame_data_.shade_history = 0u;
    frame_data_.taa_history = 0u;
    frame_data_.still_frames = 0u;
    std::memcpy(frame_->data(), &frame_data_, sizeof frame_data_);
    frame_->flush();
}

bool FrameExecutor::take_history(const FrameExecutor& from) {
    const std::vector<std::string> names = taa_history_images(graph_);
    const bool holds = from.history_valid_ || from.taa_taken_;
    if (names.empty() || !holds || taa_history_images(from.graph_) != names || graph_.output_width != from.graph_.output_width ||
        graph_.output_height != from.graph_.output_height)
        return false;
    forget_history();
    const bool shared = std::all_of(names.begin(), names.end(), [&](const std::string& n) {
        return images_.at(n) == from.images_.at(n);
    });
    if (shared && from.history_copies_.empty()) {
        // The same images: this executor's next frame reads what `from`'s next frame would have.
        parity_ = (from.parity() + 2 - frames_run_ % 2) % 2;
    } else {
        for (std::size_t i = 0; i < names.size(); ++i) {
            // What `from` last resolved, or, where it took a history and has not run since, what it took.
            const vk::StorageImage* source = from.history_copies_.empty() ? from.resolve_image(names[i], from.parity() + 1)
                                                                          : from.history_copies_[i].first;
            history_copies_.emplace_back(source, resolve_image(previous(names[i]), parity()));
        }
    }
    // The previous eyes unjittered and re-expressed in this graph's marched pixels: the taa pass
    // finds a point's place in the history from them, this frame's marched size and its factor.
    // Both marched frusta start at the output's top left, and an output pixel spans the same angle.
    const glm::vec2 from_span = glm::vec2(from.frame_data_.eye_size) * static_cast<float>(from.graph_.settings.taa_upscale());
    const glm::vec2 span = glm::vec2(graph_.width, graph_.height) * static_cast<float>(graph_.settings.taa_upscale());
    for (int eye = 0; eye < 2; ++eye) {
        GpuView v = from.previous_views_[eye];
        const glm::vec4 f = unjittered_fov(v, from.previous_jitter_, from.frame_data_.eye_size);
        const glm::vec2 per_pixel = glm::vec2(f.y - f.x, f.w - f.z) / from_span;
        v.tan_fov = {f.x, f.x + per_pixel.x * span.x, f.w - per_pixel.y * span.y, f.w};
        previous_views_[eye] = v;
    }
    previous_jitter_ = glm::vec2(0.0f);
    still_frames_ = from.still_frames_;
    history_frames_ = from.history_frames();
    taa_taken_ = true;
    return true;
}

void FrameExecutor::set_sampled_tiles(int view, std::optional<SampledTiles> sampled) {
    sampled_tiles_.at(static_cast<std::size_t>(view)) = std::move(sampled);
    ++sampled_version_;
}

void FrameExecutor::update_tile_lists() {
    for (const auto& b : graph_.buffers()) {
        if (!b.tiles) continue;
        const auto [view, region] = *b.tiles;
        const GpuView& v = frame_data_.views[view];
        std::array<float, 8> placed_by{static_cast<float>(frame_data_.eye_size.x), static_cast<float>(frame_data_.eye_size.y),
                                       v.lens_centre.x, v.lens_centre.y, v.lens_radii.x, v.lens_radii.y,
                                       frame_data_.fovea_radius, frame_data_.fovea_blend};
        TileList& list = tile_lists_[b.name];
        if (!list.placed || list.placed_by != placed_by) {
            list.placed = true;
            list.placed_by = placed_by;
            list.placed_at = frames_run_;
            list.outside_left = false;
        } else if (!list.outside_left && frames_run_ >= list.placed_at + frames_to_fill_) {
            list.outside_left = true;
        } else if (list.sampled_version == sampled_version_) {
            continue;
        }
        list.sampled_version = sampled_version_;
        list.tiles = list_dispatch_tiles(frame_data_, view, region, list.outside_left ? OutsideLens::Left : OutsideLens::Listed);
        const auto& sampled = sampled_tiles_[static_cast<std::size_t>(view)];
        if (sampled && (region == TileRegion::Whole || region == TileRegion::Fovea)) keep_sampled_tiles(list.tiles, *sampled);
        if (list.tiles.size() * 4 > b.size)
            throw std::logic_error(fmt::format("{} tiles for {}, which holds {}", list.tiles.size(), b.name, b.size / 4));
        list.written = false;
    }
}

void FrameExecutor::set_scene(const GpuScene& scene) {
    // Shading history and temporal anti-aliasing hold colours lit by the old light and background;
    // the fade comes after it.
    GpuScene unfaded = scene;
    unfaded.fade = scene_data_.fade;
    if ((graph_.shade_history || graph_.taa) && std::memcmp(&unfaded, &scene_data_, sizeof scene) != 0) forget_history();
    scene_data_ = scene;
    std::memcpy(scene_->data(), &scene, sizeof scene);
    scene_->flush();
}

bool FrameExecutor::set_param(const std::string& name, const Constant& value) {
    const auto* p = manifest_.find_param(name);
    if (!p) return false;
    forget_history();
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

namespace {

// Everything a pass may do, as the first and second scope of the barrier between two batches: a
// later pass may read (also as indirect dispatch sizes) or overwrite what an earlier one wrote.
const vk::Access kPassAccess{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};

std::array<std::uint32_t, 3> group_count(const FramePass& pass, const ManifestPass& mp, const vk::Context& ctx,
                                         std::uint64_t requested_invocations) {
    if (pass.persistent_lanes) {
        // The queue hands out whole 8x8 tiles.
        auto tiles = [](std::uint32_t n) { return (std::uint64_t(n) + 7) / 8; };
        std::uint64_t indices = tiles(pass.invocations[0]) * tiles(pass.invocations[1]) * 64 * pass.invocations[2];
        std::uint64_t fill = persistent_fill(indices, ctx.is_cpu_device(), ctx.resident_invocations(), requested_invocations);
        return {persistent_group_count(indices, mp.local_size[0] * mp.local_size[1] * mp.local_size[2], fill), 1, 1};
    }
    std::array<std::uint32_t, 3> groups{};
    for (int i = 0; i < 3; ++i) groups[i] = (pass.invocations[i] + mp.local_size[i] - 1) / std::max(1u, mp.local_size[i]);
    return groups;
}

}  // namespace

void FrameExecutor::record(VkCommandBuffer cmd, vk::GpuTimer* timer) {
    if (!images_initialised_) {
        // Zeros rather than whatever the memory held: an image a pass reads before any writes (a
        // placeholder, a history image on the first frame) holds the same bytes on every run.
        const VkClearColorValue zero{};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        for (auto& [name, versions] : images_) {
            if (std::find(adopted_.begin(), adopted_.end(), name) != adopted_.end()) continue;   // may hold a history
            for (auto& img : versions) {
                img->transition(cmd, VK_IMAGE_LAYOUT_GENERAL, vk::access::none, vk::access::transfer_write);
                vkCmdClearColorImage(cmd, img->handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &all);
            }
        }
        vk::memory_barrier(cmd, vk::access::transfer_write, vk::access::compute_read_write);
        images_initialised_ = true;
    }
    if (!history_copies_.empty()) {
        // Another executor's passes wrote the sources in an earlier submission (take_history). Both
        // images go back to GENERAL, the layout their passes and trackers expect.
        const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        for (const auto& [source, target] : history_copies_) {
            vk::image_layout_barrier(cmd, source->handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                     vk::access::anything, vk::access::transfer_read);
            vk::image_layout_barrier(cmd, target->handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                     vk::access::anything, vk::access::transfer_write);
            VkImageCopy region{layers, {0, 0, 0}, layers, {0, 0, 0}, {target->extent().width, target->extent().height, 1}};
            vkCmdCopyImage(cmd, source->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target->handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            vk::image_layout_barrier(cmd, source->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                                     vk::access::transfer_read, vk::access::anything);
            vk::image_layout_barrier(cmd, target->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                                     vk::access::transfer_write, vk::access::compute_read_write);
        }
    }
    // What earlier frames (earlier submissions) wrote or read, before this frame touches it again:
    // history images are read, every other image is overwritten.
    vk::memory_barrier(cmd, {kPassAccess.stage | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, kPassAccess.access | VK_ACCESS_2_TRANSFER_READ_BIT},
                       {kPassAccess.stage | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, kPassAccess.access | VK_ACCESS_2_TRANSFER_WRITE_BIT});
    for (const auto& b : graph_.buffers())
        if (!b.reset.empty())
            vkCmdUpdateBuffer(cmd, buffers_.at(b.name)->handle(), 0, b.reset.size() * 4, b.reset.data());
    for (auto& [name, list] : tile_lists_) {
        if (list.written) continue;
        // vkCmdUpdateBuffer takes at most 64 KiB at a time.
        constexpr std::size_t kChunk = 16384;
        for (std::size_t at = 0; at < list.tiles.size(); at += kChunk)
            vkCmdUpdateBuffer(cmd, buffers_.at(name)->handle(), at * 4, std::min(kChunk, list.tiles.size() - at) * 4,
                              list.tiles.data() + at);
        list.written = true;
    }
    vk::transfer_to_compute_barrier(cmd);
    if (timer) timer->begin(cmd, "frame");
    // One interval per run of passes with the same timer label, not one per pass: on lavapipe every
    // timestamp flushes and wakes the rasteriser's threads, and two around each of a foveated per-eye
    // frame's 18 passes kept its two compute threads from working side by side (docs/accuracy.md,
    // "Timestamps on lavapipe").
    auto timed = [&](std::size_t i) -> const std::string& {
        const FramePass& pass = graph_.passes()[i];
        return graph_.settings.time_each_pass ? pass.label : pass.timer;
    };
    const std::string* open = nullptr;   // the label of the interval running
    for (std::size_t batch = 0; batch < batches_.size(); ++batch) {
        if (batch > 0) vk::memory_barrier(cmd, kPassAccess, kPassAccess);
        for (std::size_t i : batches_[batch]) {
            const auto& pass = graph_.passes()[i];
            const Program& prog = *pass_programs_[i];
            VkDescriptorSet set = sets_[i][parity() % 2];
            if (timer && (!open || *open != timed(i))) {
                if (open) timer->end(cmd, *open);
                open = &timed(i);
                timer->begin(cmd, *open);
            }
            if (!pass.tile_list.empty()) {
                const auto& tiles = tile_lists_[pass.tile_list].tiles;
                if (!tiles.empty()) {
                    auto g = tile_dispatch_groups(tiles.size());
                    prog.kept->pipeline.dispatch(cmd, set, {g[0], g[1], g[2]}, pass.push);
                }
            } else if (pass.indirect.empty()) {
                auto g = group_count(pass, *prog.manifest, ctx_, graph_.settings.persistent_invocations);
                prog.kept->pipeline.dispatch(cmd, set, {g[0], g[1], g[2]}, pass.push);
            } else {
                prog.kept->pipeline.dispatch_indirect(cmd, set, buffers_.at(pass.indirect)->handle(), 0, pass.push);
            }
        }
    }
    if (open) timer->end(cmd, *open);
    if (timer) timer->end(cmd, "frame");
    vk::compute_to_host_barrier(cmd);
}

FrameStats FrameExecutor::run() {
    FrameStats stats;
    std::fill_n(counters_->data(), counters_->size(), std::byte{0});
    counters_->flush();
    std::unique_ptr<vk::GpuTimer> timer;
    if (ctx_.timestamps_supported())
        timer = std::make_unique<vk::GpuTimer>(ctx_, static_cast<std::uint32_t>(graph_.passes().size() + 2));
    vk::OneShot shot(ctx_);
    if (timer) timer->reset(shot.cmd());
    record(shot.cmd(), timer.get());
    shot.submit_and_wait();
    ++frames_run_;
    previous_views_[0] = frame_data_.views[FG_VIEW_LEFT];
    previous_views_[1] = frame_data_.views[FG_VIEW_RIGHT];
    previous_jitter_ = {frame_data_.jitter.x, frame_data_.jitter.y};
    still_frames_ = frame_data_.still_frames;
    history_frames_ = history_valid_ || taa_taken_ ? history_frames_ + 1 : 1;
    history_valid_ = true;
    taa_taken_ = false;
    history_copies_.clear();
    if (timer) stats.gpu_ms = timer->results();
    counters_->invalidate();
    const auto* counts = reinterpret_cast<const std::uint32_t*>(counters_->data());
    std::uint64_t total = 0, iterations = 0;
    for (std::size_t i = 0; i < graph_.counter_groups().size(); ++i) {
        const std::string& group = graph_.counter_groups()[i];
        const std::uint32_t* slot = counts + FG_COUNTER_WORDS * i;
        stats.evaluations[group] = slot[0];
        total += slot[0];
        stats.iterations[group] = slot[5];
        iterations += slot[5];
        if (slot[2] > 0) stats.lanes[group] = {slot[1], slot[2]};
        if (slot[3] > 0) stats.reuse_skipped[group] = slot[4] / 1000.0 / slot[3];
    }
    stats.evaluations_per_pixel = static_cast<double>(total) / (2.0 * graph_.output_width * graph_.output_height);
    stats.iterations_per_pixel = static_cast<double>(iterations) / (2.0 * graph_.output_width * graph_.output_height);
    return stats;
}

std::vector<std::byte> FrameExecutor::download(const std::string& image) const {
    // The frame just run has parity() - 1's parity.
    vk::StorageImage* img = resolve_image(image, parity() + 1);
    if (!img) throw std::runtime_error(fmt::format("the frame graph has no image '{}'", image));
    return img->download();
}

vk::StorageImage& FrameExecutor::image(const std::string& name) const {
    vk::StorageImage* img = resolve_image(name, parity() + 1);
    if (!img) throw std::runtime_error(fmt::format("the frame graph has no image '{}'", name));
    return *img;
}

}  // namespace fg
