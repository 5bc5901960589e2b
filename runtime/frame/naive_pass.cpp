// The baseline tracer's place in the frame graph (shader: shaders/naive.comp): plain sphere tracing
// of every output view, in naive stereo mode only.
#include "frame_graph.h"
#include "resolve_pass.h"

namespace fg {

void add_naive_passes(FrameGraph& g) {
    if (g.settings.stereo != StereoMode::Naive) return;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        g.add_image({"depth." + eye, g.width, g.height, ImageFormat::R32F, "hit distance or miss"});
        bool glow = g.effects.has(Effect::Glow);
        if (glow) g.add_image({"glow." + eye, g.width, g.height, ImageFormat::R32F, "closest approach along the ray"});
        std::string lanes = "lanes." + eye;
        if (g.persistent_lanes) g.add_buffer({lanes, 8, {0, 0}, "next pixel of each dispatch", {}});
        std::string rays = add_rays_buffer(g, view, g.width, g.height);
        std::int32_t slot = g.counter_slot("march");
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p;
            p.label = "naive." + eye;
            p.program = "naive";
            p.timer = "march";
            p.bind("fg_depth", "depth." + eye, Access::Write);
            if (glow) p.bind("fg_glow", "glow." + eye, Access::Write);
            if (g.persistent_lanes) {
                p.bind("FgLaneQueue", lanes, Access::ReadWrite);
                p.bind("FgRays", rays, Access::Write);
            } else {
                p.leave_unused("FgLaneQueue");
                p.leave_unused("FgRays");
            }
            p.persistent_lanes = g.persistent_lanes;
            p.counter_slot = slot;
            p.set_push(NaivePush{view, slot, stride});
            return p;
        });
        if (g.persistent_lanes) add_resolve_pass(g, view, g.width, g.height, "");
    }
}

}  // namespace fg
