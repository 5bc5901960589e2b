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
    // Shading reuse: the right eye reads the left eye's shading (shaded first) where both see the
    // same point. The program declares the other eye's images either way.
    // A mono view (a panorama) binds its own images there.
    std::string other = view == kCentreView ? eye : view_name(view == kLeftView ? kRightView : kLeftView);
    std::string other_out = (post ? "color." : "final.") + other;
    auto knob = g.settings.knobs.find("shade_reuse");
    bool reuse = view == kRightView && knob != g.settings.knobs.end() && knob->second > 0.0;
    p.bindings = {{"fg_depth", "depth." + eye}, {"fg_color", out}, {"fg_other_color", other_out},
                  {"fg_other_depth", "depth." + other}};
    p.reads = {"depth." + eye};
    if (reuse) {
        p.reads.push_back("depth." + other);
        p.reads.push_back(other_out);
    }
    p.writes = {out};
    p.push = {view, reuse ? 1 : 0};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pixel_pass(std::move(p), view);
}

}  // namespace fg
