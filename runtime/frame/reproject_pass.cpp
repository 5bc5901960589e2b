// Stereo reprojection in the frame graph (shader: shaders/reproject.comp): each eye walks the
// centre eye's conemarch levels, then fixes up with its own march.
#include "frame_graph.h"

namespace fg {

void add_reproject_passes(FrameGraph& g) {
    if (g.settings.stereo != StereoMode::Reproject || g.is_panorama()) return;
    for (int view : {kLeftView, kRightView}) {
        std::string eye = view_name(view);
        std::string depth = "depth." + eye;
        g.add_image({depth, g.width, g.height, ImageFormat::R32F, "hit distance or miss"});
        bool glow = g.effects.has(Effect::Glow);
        if (glow) g.add_image({"glow." + eye, g.width, g.height, ImageFormat::R32F, "closest approach along the ray"});
        std::int32_t slot = g.counter_slot("reproject");
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p;
            p.label = "reproject." + eye;
            p.program = "reproject";
            p.timer = "reproject";
            p.bind("fg_centre_levels", "cone.centre", Access::Read);
            p.bind("fg_depth", depth, Access::Write);
            if (glow) {
                p.bind("fg_centre_glow", "glow.centre", Access::Read);
                p.bind("fg_glow", "glow." + eye, Access::Write);
            }
            p.counter_slot = slot;
            p.set_push(ReprojectPush{view, slot, static_cast<std::int32_t>(std::max(1u, g.settings.cone_levels)), stride});
            return p;
        });
    }
}

}  // namespace fg
