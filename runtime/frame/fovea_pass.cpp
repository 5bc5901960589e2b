// Fixed foveation's fill pass in the frame graph (shader: shaders/fovea.comp): runs last, on the
// final image and the depth, only when foveation is on.
#include "frame_graph.h"

namespace fg {

void add_fovea_passes(FrameGraph& g) {
    if (g.settings.foveation <= 0.0) return;
    for (int view : {kLeftView, kRightView}) {
        std::string eye = view_name(view);
        FramePass p;
        p.label = "fovea." + eye;
        p.program = "fovea";
        p.timer = "fovea";
        p.bind("fg_depth", "depth." + eye, Access::ReadWrite);
        p.bind("fg_final", g.shaded_image(view), Access::ReadWrite);
        p.set_push(FoveaPush{view});
        p.invocations = {(g.width + 1) / 2, (g.height + 1) / 2, 1};   // one per 2x2 block
        g.dispatch_tiles(p, view, TileRegion::Fill);
        g.add_pass(std::move(p));
    }
}

}  // namespace fg
