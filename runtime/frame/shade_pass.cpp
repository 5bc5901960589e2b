// Shading in the frame graph (shader: shaders/shade.comp): writes the final image directly when
// the pack has no post effects, or an HDR colour image for the post pass.
#include "frame_graph.h"

namespace fg {

void add_shade_passes(FrameGraph& g) {
    auto knob = g.settings.knobs.find("shade_reuse");
    const bool reuse_knob = knob != g.settings.knobs.end() && knob->second > 0.0;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        bool post = g.has_post;
        std::string out = post ? "color." + eye : "final." + eye;
        g.add_image({out, g.width, g.height, post ? ImageFormat::RGBA16F : ImageFormat::RGBA8,
                     post ? "shaded colour (HDR)" : "final image"});
        // Shading reuse: the right eye reads the left eye's shading (shaded first) where both see
        // the same point. The program declares the other eye's images either way; without reuse
        // they are this eye's own, so the eyes stay independent.
        bool reuse = view == kRightView && reuse_knob;
        std::string other = reuse ? view_name(kLeftView) : eye;
        std::string other_out = (post ? "color." : "final.") + other;
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
            p.bind("fg_color", out, Access::Write);
            p.bind("fg_other_color", other_out, Access::Read);
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
