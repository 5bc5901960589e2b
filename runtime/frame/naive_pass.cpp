// The baseline tracer's place in the frame graph (shader: shaders/naive.comp).
#include "frame_graph.h"

namespace fg {

void add_naive_passes(FrameGraph& g, int view) {
    std::string eye = view_name(view);
    g.add_image({"depth." + eye, g.width, g.height, ImageFormat::R32F, "hit distance or miss"});
    FramePass p;
    p.label = "naive." + eye;
    p.program = "naive";
    p.timer = "march";
    p.bindings = {{"fg_depth", "depth." + eye}};
    p.writes = {"depth." + eye};
    if (g.effects.has(Effect::Glow)) {
        g.add_image({"glow." + eye, g.width, g.height, ImageFormat::R32F, "closest approach along the ray"});
        p.bindings.push_back({"fg_glow", "glow." + eye});
        p.writes.push_back("glow." + eye);
    }
    p.counter_slot = g.counter_slot("march");
    p.push = {view, p.counter_slot};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pixel_pass(std::move(p), view);
}

}  // namespace fg
