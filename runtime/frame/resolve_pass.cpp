// Persistent lanes write each pixel's result into a buffer as its ray ends; the resolve pass moves
// them into the view's images with coherent stores (shader: shaders/resolve.comp).
#include "resolve_pass.h"

namespace fg {

std::string add_rays_buffer(FrameGraph& g, int view, std::uint32_t width, std::uint32_t height) {
    std::string rays = std::string("rays.") + view_name(view);
    if (g.persistent_lanes) g.add_buffer({rays, 16ull * width * height, {}, "each pixel's result as its lane finished it", {}});
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
    // The naive tracer has no atlas: its program's binding is left unused.
    if (levels.empty()) p.leave_unused("fg_levels");
    else p.bind("fg_levels", levels, Access::Write);
    p.set_push(ResolvePush{view, levels.empty() ? 0 : 1});
    p.invocations = {width, height, 1};
    g.add_pass(std::move(p));
}

}  // namespace fg
