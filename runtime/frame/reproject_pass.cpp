// Stereo reprojection in the frame graph (shader: shaders/reproject.comp): each eye walks the
// centre eye's conemarch levels, then fixes up with its own march.
#include "frame_graph.h"

namespace fg {

void add_reproject_pass(FrameGraph& g, int view) {
    std::string eye = view_name(view);
    std::string depth = "depth." + eye;
    g.add_image({depth, g.width, g.height, ImageFormat::R32F, "hit distance or miss"});
    FramePass p;
    p.label = "reproject." + eye;
    p.program = "reproject";
    p.timer = "reproject";
    p.bindings = {{"fg_centre_levels", "cone.centre"}, {"fg_depth", depth}};
    p.reads = {"cone.centre"};
    p.writes = {depth};
    if (g.effects.has(Effect::Glow)) {
        g.add_image({"glow." + eye, g.width, g.height, ImageFormat::R32F, "closest approach along the ray"});
        p.bindings.push_back({"fg_centre_glow", "glow.centre"});
        p.bindings.push_back({"fg_glow", "glow." + eye});
        p.reads.push_back("glow.centre");
        p.writes.push_back("glow." + eye);
    }
    p.counter_slot = g.counter_slot("reproject");
    p.push = {view, p.counter_slot, static_cast<std::int32_t>(std::max(1u, g.settings.cone_levels))};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pixel_pass(std::move(p), view);
}

}  // namespace fg
