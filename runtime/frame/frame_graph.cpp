#include "frame_graph.h"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>


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
        case ImageFormat::RGBA8: return "rgba8";
    }
    return "?";
}

const char* view_name(int view) { return view == kLeftView ? "left" : view == kRightView ? "right" : "centre"; }

const FrameImage* FrameGraph::find_image(const std::string& name) const {
    for (const auto& i : images_)
        if (i.name == name) return &i;
    return nullptr;
}

void FrameGraph::add_image(FrameImage image) {
    if (!find_image(image.name)) images_.push_back(std::move(image));
}

void FrameGraph::add_buffer(FrameBuffer buffer) {
    for (const auto& b : buffers_)
        if (b.name == buffer.name) return;
    buffers_.push_back(std::move(buffer));
}

void FrameGraph::add_pass(FramePass pass) { passes_.push_back(std::move(pass)); }

void FrameGraph::add_pixel_pass(FramePass pass, int view) {
    bool foveated = settings.foveation > 0.0 && view != kCentreView;
    if (foveated) {
        FramePass periphery = pass;
        periphery.label += ".periphery";
        periphery.push.push_back(2);
        periphery.groups[0] = (pass.groups[0] + 1) / 2;
        periphery.groups[1] = (pass.groups[1] + 1) / 2;
        pass.push.push_back(1);
        add_pass(std::move(pass));
        add_pass(std::move(periphery));
        return;
    }
    pass.push.push_back(1);
    add_pass(std::move(pass));
}

std::int32_t FrameGraph::counter_slot(const std::string& group) {
    auto it = std::find(counter_groups_.begin(), counter_groups_.end(), group);
    if (it != counter_groups_.end()) return static_cast<std::int32_t>(it - counter_groups_.begin());
    counter_groups_.push_back(group);
    return static_cast<std::int32_t>(counter_groups_.size() - 1);
}

namespace {

void require_pass(const PackManifest& manifest, const char* program) {
    if (!manifest.find_pass(program))
        throw std::runtime_error(fmt::format("the pack has no '{}' pass: recompile it with this fgc", program));
}

// Panoramas run only what their rays allow. Equirect has one eye at the head's centre: the centre
// view. ODS moves each eye with every column, so there is no centre eye to reproject from: each
// eye is cone-marched on its own, its cones widened by how far the eyes of a block sit apart
// (fg_origin_spread). Reprojection asked for becomes per-eye cone marching; naive stays naive.
void add_panorama_passes(FrameGraph& g, const PackManifest& manifest) {
    std::vector<int> views = is_mono(g.settings.projection) ? std::vector<int>{kCentreView}
                                                             : std::vector<int>{kLeftView, kRightView};
    bool naive = g.settings.stereo == StereoMode::Naive;
    require_pass(manifest, naive ? "naive" : "conemarch");
    for (int view : views) {
        if (naive) add_naive_passes(g, view);
        else add_conemarch_passes(g, view);
    }
    for (int view : views) add_shade_pass(g, view);
    if (g.has_post)
        for (int view : views) add_post_pass(g, view);
}

}  // namespace

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
    if (settings.projection != Projection::Perspective) {
        // The lens mask and foveation are the headset's: a panorama has neither lens nor gaze.
        g.settings.lens_mask = false;
        g.settings.foveation = 0.0;
    }
    g.effects = manifest.effects;
    g.has_post = manifest.find_pass("post") != nullptr;
    g.manifest_has_tail = manifest.find_pass("tail") != nullptr;
    if (const auto* tail = manifest.find_spec("tail_after")) {
        auto it = settings.knobs.find("tail_after");
        g.tail_after = static_cast<std::uint32_t>(it != settings.knobs.end() ? it->second : tail->value);
    }
    auto require = [&](const char* program) { require_pass(manifest, program); };
    require("shade");
    if (settings.projection != Projection::Perspective) {
        add_panorama_passes(g, manifest);
        return g;
    }
    switch (settings.stereo) {
        case StereoMode::Naive:
            require("naive");
            for (int eye : {kLeftView, kRightView}) add_naive_passes(g, eye);
            break;
        case StereoMode::PerEye:
            require("conemarch");
            for (int eye : {kLeftView, kRightView}) add_conemarch_passes(g, eye);
            break;
        case StereoMode::Reproject:
            require("conemarch");
            require("reproject");
            add_conemarch_passes(g, kCentreView);
            for (int eye : {kLeftView, kRightView}) add_reproject_pass(g, eye);
            break;
    }
    for (int eye : {kLeftView, kRightView}) add_shade_pass(g, eye);
    if (g.has_post)
        for (int eye : {kLeftView, kRightView}) add_post_pass(g, eye);
    if (g.settings.foveation > 0.0) {
        require("fovea");
        for (int eye : {kLeftView, kRightView}) add_fovea_pass(g, eye);
    }
    return g;
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
    auto names = effects.names();
    s += "effects: " + (names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "))) + "\n";
    std::size_t bytes = 0;
    s += fmt::format("images and buffers ({}):\n", images_.size() + buffers_.size());
    for (const auto& i : images_) {
        std::size_t px = static_cast<std::size_t>(i.width) * i.height;
        std::size_t bpp = i.format == ImageFormat::R32F ? 4 : i.format == ImageFormat::RGBA8 ? 4 : 8;
        if (i.format == ImageFormat::RGBA16F) bpp = 8;
        bytes += px * bpp;
        s += fmt::format("  {:<16} {:>5}x{:<5} {:<8} {}\n", i.name, i.width, i.height, image_format_name(i.format), i.about);
    }
    for (const auto& b : buffers_) {
        bytes += b.size;
        s += fmt::format("  {:<16} {:>11} B        {}\n", b.name, b.size, b.about);
    }
    s += fmt::format("  ({:.1f} MiB)\n", static_cast<double>(bytes) / (1024.0 * 1024.0));
    s += fmt::format("passes ({}):\n", passes_.size());
    for (const auto& p : passes_) {
        std::string groups = p.indirect.empty() ? fmt::format("{:>4}x{:<4}", p.groups[0], p.groups[1])
                                                : fmt::format("{:<9}", "indirect");
        s += fmt::format("  {:<20} {:<10} {} reads [{}] writes [{}]\n", p.label, p.program, groups,
                         fmt::join(p.reads, ", "), fmt::join(p.writes, ", "));
    }
    return s;
}

}  // namespace fg
