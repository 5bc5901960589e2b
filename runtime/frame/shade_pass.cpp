// Shading in the frame graph (shader: shaders/shade.comp): shades each hit, applies the post effects
// the pack lists and the tone map, and writes the final image.
#include "frame_graph.h"

namespace fg {

void add_shade_passes(FrameGraph& g) {
    auto knob = g.settings.knobs.find("shade_reuse");
    const bool reuse_knob = knob != g.settings.knobs.end() && knob->second > 0.0;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        g.add_image({"final." + eye, g.width, g.height, ImageFormat::RGBA8, "final image"});
        // Shading reuse: each eye keeps its colour before post effects; the right eye reads the left
        // eye's (shaded first) where both see the same point. The program declares these images
        // either way: without the knob they are one pixel, never written, and each eye's "other" is
        // its own, so the eyes stay independent.
        const std::string shaded = reuse_knob ? "color." + eye : "color." + eye + ".off";
        if (reuse_knob)
            g.add_image({shaded, g.width, g.height, ImageFormat::RGBA16F, "shaded colour before post (shading reuse)"});
        else
            g.add_image({shaded, 1, 1, ImageFormat::RGBA16F, "(shading reuse off)"});
        bool reuse = view == kRightView && reuse_knob;
        std::string other = reuse ? view_name(kLeftView) : eye;
        // Shading history: this eye's colours before post and tone map, with their age, and their
        // hit distances, kept for the next frame. Without it the program still declares them: one
        // pixel each, never written.
        const bool history = g.shade_history;
        const std::string cache = "shade_cache." + eye, cache_depth = "shade_depth." + eye;
        if (history) {
            g.add_image({cache, g.width, g.height, ImageFormat::RGBA16F, "shading before post, its age (history)"});
            g.add_image({cache_depth, g.width, g.height, ImageFormat::R32F, "hit distance of the shading (history)"});
            g.keep_for_next_frame(cache);
            g.keep_for_next_frame(cache_depth);
        } else {
            g.add_image({cache + ".off", 1, 1, ImageFormat::RGBA16F, "(shading history off)"});
            g.add_image({cache_depth + ".off", 1, 1, ImageFormat::R32F, "(shading history off)"});
        }
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p;
            p.label = "shade." + eye;
            p.program = "shade";
            p.timer = "shade";
            p.bind("fg_depth", "depth." + eye, Access::Read);
            p.bind("fg_final", "final." + eye, Access::Write);
            if (g.effects.has(Effect::Glow)) p.bind("fg_glow", "glow." + eye, Access::Read);
            p.bind("fg_shaded", shaded, Access::Write);
            p.bind("fg_other_color", reuse ? "color." + other : shaded, Access::Read);
            p.bind("fg_other_depth", "depth." + other, Access::Read);
            p.bind("fg_history_color", history ? previous(cache) : cache + ".off", Access::Read);
            p.bind("fg_history_depth", history ? previous(cache_depth) : cache_depth + ".off", Access::Read);
            p.bind("fg_cache_color", history ? cache : cache + ".off", Access::Write);
            p.bind("fg_cache_depth", history ? cache_depth : cache_depth + ".off", Access::Write);
            p.set_push(ShadePush{view, reuse ? 1 : 0, stride});
            return p;
        });
    }
}

}  // namespace fg
