// Fixed foveation's fill pass in the frame graph (shader: shaders/fovea.comp): runs last, on the
// final image and the depth, only when foveation is on.
#include "frame_graph.h"

namespace fg {

void add_fovea_pass(FrameGraph& g, int view) {
    std::string eye = view_name(view);
    FramePass p;
    p.label = "fovea." + eye;
    p.program = "fovea";
    p.timer = "post";
    p.bindings = {{"fg_depth", "depth." + eye}, {"fg_final", "final." + eye}};
    p.reads = {"depth." + eye, "final." + eye};
    p.writes = {"depth." + eye, "final." + eye};
    p.push = {view};
    p.groups[0] = (g.width + 7) / 8;
    p.groups[1] = (g.height + 7) / 8;
    g.add_pass(std::move(p));
}

}  // namespace fg
