// Persistent lanes write each pixel's result into a buffer as its ray ends; the resolve pass moves
// them into the view's images with coherent stores (shader: shaders/resolve.comp).
#include "resolve_pass.h"

namespace fg {

std::string add_rays_buffer(FrameGraph& g, int view, std::uint32_t width, std::uint32_t height) {
    std::string rays = std::string("rays.") + view_name(view);
    g.add_buffer({rays, g.persistent_lanes ? 16ull * width * height : 16, {},
                  g.persistent_lanes ? "each pixel's result as its lane finished it" : "(persistent lanes off)", {}});
    return rays;
}

void add_resolve_pass(FrameGraph& g, int view, std::uint32_t width, std::uint32_t height, const std::string& levels) {
    std::string eye = view_name(view);
    FramePass p;
    p.label = "resolve." + eye;
    p.program = "resolve";
    p.timer = "march";
    p.bind("FgRays", "rays." + eye, Access::Read);
    p.bind("fg_depth", "depth." + eye, Access::Write);
    if (g.effects.has(Effect::Glow)) p.bind("fg_glow", "glow." + eye, Access::Write);
    // The naive tracer has no atlas: the program's binding gets a stand-in it never writes.
    std::string atlas = levels;
    if (atlas.empty()) {
        atlas = "levels.none";
        g.add_image({atlas, 1, 1, ImageFormat::RG32F, "(the naive tracer has no cone levels)"});
    }
    p.bind("fg_levels", atlas, Access::Write);
    p.set_push(ResolvePush{view, levels.empty() ? 0 : 1});
    p.invocations = {width, height, 1};
    g.add_pass(std::move(p));
}

}  // namespace fg
