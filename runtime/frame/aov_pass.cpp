// The AOV pass in the frame graph (shader: shaders/aov.comp): only when an offline render asks for
// the picture's terms (FrameSettings::aovs, OpenEXR output). It runs after the picture is done and
// reads only its depth (and glow), so the picture itself is the same with or without it.
#include "aov_images.h"
#include "frame_graph.h"

namespace fg {

void add_aov_passes(FrameGraph& g) {
    if (!g.settings.aovs) return;
    for (int view : g.output_views()) {
        std::string eye = view_name(view);
        FramePass p;
        p.label = "aov." + eye;
        p.program = "aov";
        p.timer = "aov";
        p.bind("fg_depth", "depth." + eye, Access::Read);
        if (g.effects.has(Effect::Glow)) p.bind("fg_glow", "glow." + eye, Access::Read);
        for (const AovImage& a : aov_images()) {
            if (!aov_image_needed(a, g.effects)) continue;
            g.add_image({aov_image_name(a, eye), g.width, g.height, a.format, a.about});
            p.bind(a.binding, aov_image_name(a, eye), Access::Write);
        }
        p.invocations = {g.width, g.height, 1};
        p.set_push(AovPush{view});
        g.add_pass(std::move(p));
    }
}

}  // namespace fg
