// Post effects in the frame graph (shader: shaders/post.comp): only present when the pack lists
// fog, glow or a vignette.
#include "frame_graph.h"

namespace fg {

void add_post_passes(FrameGraph& g) {
    if (!g.has_post) return;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        g.add_image({"final." + eye, g.width, g.height, ImageFormat::RGBA8, "final image"});
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p;
            p.label = "post." + eye;
            p.program = "post";
            p.timer = "post";
            p.bind("fg_depth", "depth." + eye, Access::Read);
            p.bind("fg_color", "color." + eye, Access::Read);
            if (g.effects.has(Effect::Glow)) p.bind("fg_glow", "glow." + eye, Access::Read);
            p.bind("fg_final", "final." + eye, Access::Write);
            p.set_push(PostPush{view, stride});
            return p;
        });
    }
}

}  // namespace fg
