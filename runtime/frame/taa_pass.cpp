// Temporal anti-aliasing in the frame graph (shader: shaders/taa.comp): with it, the shade and
// fovea passes write each eye's jittered frame into `jittered.<eye>`, and this pass blends it into
// the eye's history and writes the final image. Without it, nothing.
#include "frame_graph.h"

namespace fg {

void add_taa_passes(FrameGraph& g) {
    if (!g.taa) return;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        const std::string resolved = "taa." + eye, depth = "taa_depth." + eye;
        g.add_image({resolved, g.width, g.height, ImageFormat::RGBA16F, "anti-aliased colour, linear (history)"});
        g.add_image({depth, g.width, g.height, ImageFormat::R32F, "hit distance of the jittered frame (history)"});
        g.keep_for_next_frame(resolved);
        g.keep_for_next_frame(depth);
        FramePass p;
        p.label = "taa." + eye;
        p.program = "taa";
        p.timer = "taa";
        p.bind("fg_jittered", g.shaded_image(view), Access::Read);
        p.bind("fg_depth", "depth." + eye, Access::Read);
        p.bind("fg_history", previous(resolved), Access::Read);
        p.bind("fg_history_depth", previous(depth), Access::Read);
        p.bind("fg_resolved", resolved, Access::Write);
        p.bind("fg_resolved_depth", depth, Access::Write);
        p.bind("fg_final", "final." + eye, Access::Write);
        p.set_push(TaaPush{view});
        p.invocations = {g.width, g.height, 1};
        g.add_pass(std::move(p));
    }
}

}  // namespace fg
