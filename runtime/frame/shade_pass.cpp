// Shading in the frame graph (shader: shaders/shade.comp): writes the final image directly when
// the pack has no post effects, or an HDR colour image for the post pass.
#include "frame_graph.h"

namespace fg {

void add_shade_pass(FrameGraph& g, int view) {
    std::string eye = view_name(view);
    bool post = g.has_post;
    std::string out = post ? "color." + eye : "final." + eye;
    g.add_image({out, g.width, g.height, post ? ImageFormat::RGBA16F : ImageFormat::RGBA8,
                 post ? "shaded colour (HDR)" : "final image"});
    FramePass p;
    p.label = "shade." + eye;
    p.program = "shade";
    p.timer = "shade";
    p.bindings = {{"fg_depth", "depth." + eye}, {"fg_color", out}};
    p.reads = {"depth." + eye};
    p.writes = {out};
    p.push = {view};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pixel_pass(std::move(p), view);
}

}  // namespace fg
