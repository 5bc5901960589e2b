#include "frame_graph.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>
#include <fmt/format.h>
#include <stdexcept>

#include "frame_passes.h"

namespace fg {

const char* stereo_mode_name(StereoMode m) {
    switch (m) {
        case StereoMode::Reproject: return "reproject";
        case StereoMode::PerEye: return "per-eye";
        case StereoMode::Naive: return "naive";
    }
    return "?";
}

bool parse_stereo_mode(const std::string& s, StereoMode& out) {
    for (auto m : {StereoMode::Reproject, StereoMode::PerEye, StereoMode::Naive})
        if (s == stereo_mode_name(m)) {
            out = m;
            return true;
        }
    return false;
}

const char* image_format_name(ImageFormat f) {
    switch (f) {
        case ImageFormat::R32F: return "r32f";
        case ImageFormat::RG32F: return "rg32f";
        case ImageFormat::RGBA16F: return "rgba16f";
        case ImageFormat::RGBA32F: return "rgba32f";
        case ImageFormat::RGBA8: return "rgba8";
        case ImageFormat::RGBA32UI: return "rgba32ui";
    }
    return "?";
}

std::uint32_t bytes_per_pixel(ImageFormat f) {
    if (f == ImageFormat::RGBA32F || f == ImageFormat::RGBA32UI) return 16;
    return f == ImageFormat::RG32F || f == ImageFormat::RGBA16F ? 8 : 4;
}

std::string previous(const std::string& image) { return image + ".previous"; }

std::string current(const std::string& name) {
    constexpr std::string_view kPrevious = ".previous";
    return name.ends_with(kPrevious) ? name.substr(0, name.size() - kPrevious.size()) : name;
}

const char* view_name(int view) { return view == kLeftView ? "left" : view == kRightView ? "right" : "centre"; }

void FramePass::bind(const std::string& binding, const std::string& resource, Access access) {
    bindings.emplace_back(binding, resource);
    auto add = [&](std::vector<std::string>& list) {
        if (std::find(list.begin(), list.end(), resource) == list.end()) list.push_back(resource);
    };
    if (access != Access::Write) add(reads);
    if (access != Access::Read) add(writes);
}

bool FramePass::reads_resource(const std::string& r) const {
    return std::find(reads.begin(), reads.end(), r) != reads.end() || indirect == r;
}

bool FramePass::writes_resource(const std::string& r) const {
    return std::find(writes.begin(), writes.end(), r) != writes.end();
}

const FrameImage* FrameGraph::find_image(const std::string& name) const {
    for (const auto& i : images_)
        if (i.name == name) return &i;
    return nullptr;
}

const FrameBuffer* FrameGraph::find_buffer(const std::string& name) const {
    for (const auto& b : buffers_)
        if (b.name == name) return &b;
    return nullptr;
}

void FrameGraph::add_image(FrameImage image) {
    if (const FrameImage* same = find_image(image.name)) {
        if (same->width != image.width || same->height != image.height || same->format != image.format ||
            same->history != image.history)
            throw std::logic_error(fmt::format("the frame graph's image {} is {}x{} {}, and a pass asks for {}x{} {} under "
                                               "the same name",
                                               image.name, same->width, same->height, image_format_name(same->format),
                                               image.width, image.height, image_format_name(image.format)));
        return;
    }
    if (find_buffer(image.name)) throw std::logic_error(fmt::format("{} names a buffer and an image", image.name));
    images_.push_back(std::move(image));
}

void FrameGraph::add_buffer(FrameBuffer buffer) {
    if (const FrameBuffer* same = find_buffer(buffer.name)) {
        if (same->size != buffer.size || same->reset != buffer.reset)
            throw std::logic_error(fmt::format("the frame graph's buffer {} is {} bytes, and a pass asks for {} under the "
                                               "same name",
                                               buffer.name, same->size, buffer.size));
        return;
    }
    if (find_image(buffer.name)) throw std::logic_error(fmt::format("{} names an image and a buffer", buffer.name));
    buffers_.push_back(std::move(buffer));
}

void FrameGraph::add_pass(FramePass pass) { passes_.push_back(std::move(pass)); }

void FrameGraph::keep_for_next_frame(const std::string& image) {
    for (auto& i : images_)
        if (i.name == image) {
            i.history = true;
            return;
        }
    throw std::logic_error(fmt::format("the frame graph has no image {} to keep", image));
}

void FrameGraph::dispatch_tiles(FramePass& pass, int view, TileRegion region) {
    if (!tile_dispatch || pass.persistent_lanes) return;
    std::string name = fmt::format("tiles.{}.{}", view_name(view), tile_region_name(region));
    if (!find_buffer(name))
        add_buffer({name, 4ull * dispatch_tile_capacity(width, height, region), {},
                    fmt::format("the {} eye's {} tiles that hold pixels (8x8 cells, listed each frame the lens moves)",
                                view_name(view), tile_region_name(region)),
                    std::pair{view, region}});
    pass.bind("FgTiles", name, Access::Read);
    pass.tile_list = name;
    pass.specialize[kSpecTileList.id] = 1;
}

std::int32_t FrameGraph::counter_slot(const std::string& group) {
    auto it = std::find(counter_groups_.begin(), counter_groups_.end(), group);
    if (it != counter_groups_.end()) return static_cast<std::int32_t>(it - counter_groups_.begin());
    counter_groups_.push_back(group);
    return static_cast<std::int32_t>(counter_groups_.size() - 1);
}

std::vector<int> FrameGraph::output_views() const {
    if (is_mono(settings.projection)) return {kCentreView};
    return {kLeftView, kRightView};
}

std::vector<std::vector<std::size_t>> FrameGraph::batches() const {
    // Each pass goes one batch after the latest pass it depends on: the last writer of what it
    // reads or writes, and every reader since that write of what it writes.
    struct Seen {
        std::size_t last_write_batch = 0;
        bool written = false;
        std::size_t last_read_batch = 0;
        bool read = false;
    };
    std::map<std::string, Seen> seen;
    std::vector<std::size_t> batch_of(passes_.size(), 0);
    std::size_t count = 0;
    for (std::size_t i = 0; i < passes_.size(); ++i) {
        const FramePass& p = passes_[i];
        std::size_t b = 0;
        auto after = [&](std::size_t batch) { b = std::max(b, batch + 1); };
        std::vector<std::string> touched = p.reads;
        if (!p.indirect.empty()) touched.push_back(p.indirect);
        touched.insert(touched.end(), p.writes.begin(), p.writes.end());
        for (const auto& r : touched) {
            const Seen& s = seen[r];
            if (s.written) after(s.last_write_batch);
            if (p.writes_resource(r) && s.read) after(s.last_read_batch);
        }
        batch_of[i] = b;
        for (const auto& r : touched) {
            Seen& s = seen[r];
            if (p.writes_resource(r)) {
                s.written = true;
                s.last_write_batch = b;
                s.read = false;
                s.last_read_batch = 0;
            } else {
                s.read = true;
                s.last_read_batch = std::max(s.last_read_batch, b);
            }
        }
        count = std::max(count, b + 1);
    }
    std::vector<std::vector<std::size_t>> out(count);
    for (std::size_t i = 0; i < passes_.size(); ++i) out[batch_of[i]].push_back(i);
    return out;
}

FrameGraph FrameGraph::build(const PackManifest& manifest, const FrameSettings& settings, std::uint32_t centre_width,
                             std::uint32_t centre_height) {
    FrameGraph g;
    g.width = settings.width;
    g.height = settings.height;
    g.centre_width = centre_width;
    g.centre_height = centre_height;
    g.settings = settings;
    g.settings.camera_relative = manifest.precision == "double";
    if (g.settings.foveation < 0.0) {
        // As the scene says: its foveation block, or none.
        const auto& foveation = manifest.scene.foveation;
        g.settings.foveation = foveation ? foveation->inner_radius : 0.0;
        if (foveation) g.settings.foveation_blend = foveation->blend;
    }
    if (g.settings.hdr) g.settings.foveation = 0.0;
    if (g.is_panorama()) {
        // The lens mask and foveation are the headset's: a panorama has neither lens nor gaze. ODS
        // moves each eye with every column, so there is no centre eye to reproject from: each view
        // is cone-marched on its own (fg_origin_spread widens its cones); naive stays naive.
        g.settings.lens_mask = false;
        g.settings.foveation = 0.0;
        if (g.settings.stereo == StereoMode::Reproject) g.settings.stereo = StereoMode::PerEye;
    }
    g.effects = manifest.effects;
    // Post effects moved into the shade pass; a pack from an fgc before that carries a post pass and
    // a shade pass that writes for it, which this frame graph cannot bind.
    if (manifest.find_pass("post"))
        throw std::runtime_error("this pack has a separate post pass: it was compiled by an older fgc, whose shade pass "
                                 "this runtime cannot run; recompile it from its graph with this fgc");
    g.manifest_has_tail = manifest.find_pass("tail") != nullptr;
    auto knob = [&](const char* name) {
        auto it = settings.knobs.find(name);
        const auto* spec = manifest.find_spec(name);
        return it != settings.knobs.end() ? it->second : spec ? spec->value : 0.0;
    };
    g.tail_after = static_cast<std::uint32_t>(knob("tail_after"));
    g.persistent_lanes = knob("persistent_lanes") != 0.0 && manifest.find_spec("persistent_lanes");
    if (g.persistent_lanes && g.tail_after > 0) {
        // Persistent lanes refill every lane continuously: the tail pass's compaction has nothing
        // left to do, and its deferral would only hand pixels to a pass that is not there.
        g.tail_after = 0;
        g.settings.knobs["tail_after"] = 0.0;
    }
    // Reuse rests on the scene staying put between frames, on the eyes' own levels (per-eye
    // marching, a perspective frame), and on origins that do not move with the camera (float).
    const bool has_reuse_knob = manifest.find_spec("reuse") != nullptr;
    g.reuse = has_reuse_knob && knob("reuse") != 0.0 && !manifest.animated && !g.is_panorama() &&
              g.settings.stereo == StereoMode::PerEye && manifest.precision == "float";
    if (has_reuse_knob && !g.reuse) g.settings.knobs["reuse"] = 0.0;
    const bool has_history_knob = manifest.find_spec("shade_history") != nullptr;
    g.shade_history = has_history_knob && knob("shade_history") > 0.0 && !manifest.animated && !g.is_panorama() &&
                      manifest.precision == "float" && !g.effects.has(Effect::Rim) && !g.effects.has(Effect::Subsurface) &&
                      !g.effects.has(Effect::Specular) && !g.effects.has(Effect::Reflection) &&
                      !g.effects.has(Effect::Refraction);
    if (has_history_knob && !g.shade_history) g.settings.knobs["shade_history"] = 0.0;
    // Temporal anti-aliasing reprojects each hit into the previous frame: the scene must stay put,
    // and float origins must not move with the camera. Otherwise frames are plain, unjittered.
    g.taa = g.settings.taa && !manifest.animated && !g.is_panorama() && manifest.precision == "float" &&
            manifest.find_pass("taa") != nullptr;
    g.settings.taa = g.taa;
    if (g.taa) g.settings.hdr = false;
    if (!g.taa) g.settings.output_width = g.settings.output_height = 0;
    g.output_width = g.settings.shown_width();
    g.output_height = g.settings.shown_height();
    // What the pack's shaders can do that an older fgc's could not.
    auto declares = [&](const char* program, const DispatchConstant& c) {
        const ManifestPass* p = manifest.find_pass(program);
        return p && std::count(p->dispatch_constants.begin(), p->dispatch_constants.end(), c.id) > 0;
    };
    g.tile_dispatch = g.settings.tile_dispatch && declares("shade", kSpecTileList);
    g.periphery_from_level_2 = declares("conemarch", kSpecPeripheryParent);
    for (const auto& kind : frame_pass_kinds()) kind.add(g);
    for (const auto& p : g.passes_)
        if (!manifest.find_pass(p.program))
            throw std::runtime_error(fmt::format("the pack has no '{}' pass: recompile it with this fgc", p.program));
    return g;
}

std::string FrameGraph::shaded_image(int view) const { return (taa ? "jittered." : "final.") + std::string(view_name(view)); }

std::uint64_t FrameGraph::memory_bytes() const {
    std::uint64_t bytes = 0;
    for (const auto& i : images_)
        bytes += static_cast<std::uint64_t>(i.width) * i.height * bytes_per_pixel(i.format) * (i.history ? 2 : 1);
    for (const auto& b : buffers_) bytes += b.size;
    return bytes;
}

std::string FrameGraph::describe() const {
    std::string s = settings.projection == Projection::Perspective
                        ? fmt::format("frame graph: {} stereo, {}x{} per eye, {} cone levels\n",
                                      stereo_mode_name(settings.stereo), width, height, settings.cone_levels)
                        : fmt::format("frame graph: {} panorama, {}x{} per eye, {}\n", projection_name(settings.projection),
                                      width, height,
                                      settings.stereo == StereoMode::Naive
                                          ? std::string("naive marching")
                                          : fmt::format("{} cone levels per view", settings.cone_levels));
    s += fmt::format("pixels: lens mask {}, foveation {}\n", settings.lens_mask ? "on" : "off",
                     settings.foveation > 0.0 ? fmt::format("fovea radius {:g}, blend {:g}", settings.foveation,
                                                            settings.foveation_blend)
                                              : std::string("off"));
    if (taa)
        s += output_width == width ? "anti-aliasing: temporal (jittered rays, a history per eye)\n"
                                   : fmt::format("anti-aliasing: temporal upsampling to {}x{} per eye (jittered rays, a "
                                                 "history per eye)\n", output_width, output_height);
    auto names = effects.names();
    s += "effects: " + (names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "))) + "\n";
    s += fmt::format("images and buffers ({}):\n", images_.size() + buffers_.size());
    std::size_t name_width = 16;
    for (const auto& i : images_) name_width = std::max(name_width, i.name.size());
    for (const auto& b : buffers_) name_width = std::max(name_width, b.name.size());
    for (const auto& i : images_) {
        s += fmt::format("  {:<{}} {:>5}x{:<5} {:<8} {}{}\n", i.name, name_width, i.width, i.height,
                         image_format_name(i.format), i.about, i.history ? " (kept for the next frame)" : "");
    }
    for (const auto& b : buffers_) {
        s += fmt::format("  {:<{}} {:>11} B        {}\n", b.name, name_width, b.size, b.about);
    }
    s += fmt::format("  ({:.1f} MiB)\n", static_cast<double>(memory_bytes()) / (1024.0 * 1024.0));
    auto order = batches();
    s += fmt::format("passes ({}, {} barriers):\n", passes_.size(), order.empty() ? 0 : order.size() - 1);
    for (std::size_t b = 0; b < order.size(); ++b)
        for (std::size_t i : order[b]) {
            const FramePass& p = passes_[i];
            std::string dispatch = !p.indirect.empty() ? std::string("indirect")
                                                       : fmt::format("{}x{}{}", p.invocations[0], p.invocations[1],
                                                                     p.persistent_lanes ? " queue"
                                                                     : p.tile_list.empty() ? ""
                                                                                           : " tiles");
            s += fmt::format("  {:>2} {:<28} {:<10} {:<16} reads [{}] writes [{}]\n", b, p.label, p.program, dispatch,
                             fmt::join(p.reads, ", "), fmt::join(p.writes, ", "));
        }
    return s;
}

}  // namespace fg
