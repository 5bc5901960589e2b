// Shading in the frame graph (shader: shaders/shade.comp): shades each hit, applies the post effects
// the pack lists and the tone map, and writes the final image.
#include "frame_graph.h"

namespace fg {


void add_shade_passes(FrameGraph& g) {
    auto knob = g.settings.knobs.find("shade_reuse");
    const bool reuse_knob = knob != g.settings.knobs.end() && knob->second > 0.0;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        g.add_image({"final." + eye, g.output_width, g.output_height, ImageFormat::RGBA8, "final image"});
        if (g.taa) g.add_image({g.shaded_image(view), g.width, g.height, ImageFormat::RGBA8, "this frame's jittered samples"});
        if (g.settings.hdr) g.add_image({"hdr." + eye, g.width, g.height, ImageFormat::RGBA32F, "the tone map's input (samples average it)"});
        // Shading reuse: each eye keeps its shading before post effects, as terms (the colour without
        // the terms that read the view, and the albedo); the right eye reads the left eye's (shaded
        // first) where both see the same point. Without the knob each eye's "other" is its own, so the
        // eyes stay independent.
        const std::string shaded = "color." + eye;
        if (reuse_knob) g.add_image({shaded, g.width, g.height, ImageFormat::RGBA32UI, "shading before post as terms (shading reuse)"});
        bool reuse = view == kRightView && reuse_knob;
        std::string other = reuse ? view_name(kLeftView) : eye;
        // Shading history: this eye's shading before post and tone map as the same terms, with their
        // age, and their hit distances, kept for the next frame.
        const bool history = g.shade_history;
        const std::string cache = "shade_cache." + eye, cache_depth = "shade_depth." + eye;
        if (history) {
            g.add_image({cache, g.width, g.height, ImageFormat::RGBA32UI, "shading before post as terms, its age (history)"});
            g.add_image({cache_depth, g.width, g.height, ImageFormat::R32F, "hit distance of the shading (history)"});
            g.keep_for_next_frame(cache);
            g.keep_for_next_frame(cache_depth);
        }
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p;
            p.label = "shade." + eye;
            p.program = "shade";
            p.timer = "shade";
            p.bind("fg_depth", "depth." + eye, Access::Read);
            p.bind("fg_final", g.shaded_image(view), Access::Write);
            if (g.effects.has(Effect::Glow)) p.bind("fg_glow", "glow." + eye, Access::Read);
            if (reuse_knob) {
                p.bind("fg_shaded", shaded, Access::Write);
                p.bind("fg_other_color", reuse ? "color." + other : shaded, Access::Read);
            } else {
                p.leave_unused("fg_shaded");
                p.leave_unused("fg_other_color");
            }
            p.bind("fg_other_depth", "depth." + other, Access::Read);
            if (history) {
                p.bind("fg_history_color", previous(cache), Access::Read);
                p.bind("fg_history_depth", previous(cache_depth), Access::Read);
                p.bind("fg_cache_color", cache, Access::Write);
                p.bind("fg_cache_depth", cache_depth, Access::Write);
            } else {
                for (const char* b : {"fg_history_color", "fg_history_depth", "fg_cache_color", "fg_cache_depth"}) p.leave_unused(b);
            }
            if (g.settings.hdr) p.bind("fg_hdr", "hdr." + eye, Access::Write);
            else p.leave_unused("fg_hdr");
            p.set_push(ShadePush{view, reuse ? 1 : 0, stride, g.settings.hdr ? 1 : 0});
            return p;
        });
    }
}

}  // namespace fg
