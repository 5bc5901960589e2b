// Temporal anti-aliasing in the frame graph (shader: shaders/taa.comp): with it, the shade and
// fovea passes write each eye's jittered frame into `jittered.<eye>`, and this pass blends it into
// the eye's history and writes the final image, at the marched size or, upsampling, at the output
// size. Without it, nothing.
#include <algorithm>
#include <cmath>

#include "frame_graph.h"

namespace fg {

void set_taa_upscale(FrameSettings& f, double factor) {
    f.output_width = f.output_height = 0;
    f.taa_upscale_factor = 1.0;
    if (factor <= 1.0) return;
    f.output_width = f.width;
    f.output_height = f.height;
    f.taa_upscale_factor = factor;
    // Whole marched pixels of exactly `factor` output pixels: the last reaches past the output's
    // edge where its size is no multiple of the factor (StereoSettings::upscale).
    f.width = std::max(8u, static_cast<std::uint32_t>(std::ceil(f.output_width / factor - 1e-9)));
    f.height = std::max(8u, static_cast<std::uint32_t>(std::ceil(f.output_height / factor - 1e-9)));
    // Output pixels per marched pixel: the hit threshold follows the pixel shown.
    f.detail_scale /= factor;
}

namespace {

// A view's history images: the resolved colour and the depth of its nearest samples.
std::string resolved_image(int view) { return std::string("taa.") + view_name(view); }
std::string resolved_depth_image(int view) { return std::string("taa_depth.") + view_name(view); }

}  // namespace

std::vector<std::string> taa_history_images(const FrameGraph& g) {
    std::vector<std::string> names;
    if (!g.taa) return names;
    for (int view : g.output_views()) {
        names.push_back(resolved_image(view));
        names.push_back(resolved_depth_image(view));
    }
    return names;
}

void add_taa_passes(FrameGraph& g) {
    if (!g.taa) return;
    const std::uint32_t w = g.output_width, h = g.output_height;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        const std::string resolved = resolved_image(view), depth = resolved_depth_image(view);
        // Single precision: a still pixel's mean moves by 1/n of a sample a frame, less than a half
        // float's step after some frames, and half-float rounding then darkened a still picture by
        // 4.7 % over 300 frames.
        g.add_image({resolved, w, h, ImageFormat::RGBA32F, "anti-aliased colour, linear; alpha: the samples' weight (history)"});
        g.add_image({depth, w, h, ImageFormat::R32F, "hit distance of each pixel's nearest sample (history)"});
        g.keep_for_next_frame(resolved);
        g.keep_for_next_frame(depth);
        FramePass p;
        p.label = "taa." + eye;
        p.program = "taa";
        p.timer = "taa";
        p.bind("fg_jittered", g.shaded_image(view), Access::Read);
        p.bind("fg_depth", "depth." + eye, Access::Read);
        p.bind("fg_history", previous(resolved), Access::Read);
        p.bind("fg_history_depth", previous(depth), Access::Read);
        p.bind("fg_resolved", resolved, Access::Write);
        p.bind("fg_resolved_depth", depth, Access::Write);
        p.bind("fg_final", "final." + eye, Access::Write);
        p.set_push(TaaPush{view, static_cast<float>(g.settings.taa_upscale()), static_cast<float>(g.settings.taa_sharpen)});
        p.invocations = {w, h, 1};
        g.add_pass(std::move(p));
    }
}

}  // namespace fg
