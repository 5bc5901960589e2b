// Post effects in the frame graph (shader: shaders/post.comp): only present when the pack lists
// fog, glow, vignette or foveation.
#include "frame_graph.h"

namespace fg {

void add_post_pass(FrameGraph& g, int view) {
    std::string eye = view_name(view);
    g.add_image({"final." + eye, g.width, g.height, ImageFormat::RGBA8, "final image"});
    FramePass p;
    p.label = "post." + eye;
    p.program = "post";
    p.timer = "post";
    p.bindings = {{"fg_depth", "depth." + eye}, {"fg_color", "color." + eye}, {"fg_final", "final." + eye}};
    p.reads = {"depth." + eye, "color." + eye};
    if (g.effects.has(Effect::Glow)) {
        p.bindings.push_back({"fg_glow", "glow." + eye});
        p.reads.push_back("glow." + eye);
    }
    p.writes = {"final." + eye};
    p.push = {view};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pixel_pass(std::move(p), view);
}

}  // namespace fg
