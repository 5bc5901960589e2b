// Progressive cone marching in the frame graph (shader: shaders/conemarch.comp): one dispatch per
// level, coarse to fine, into one atlas image per view; level 0 also writes the view's depth.
#include <fmt/format.h>

#include "common/spec_constants.h"
#include "frame_graph.h"
#include "resolve_pass.h"

namespace fg {

namespace {

// Size of a level (ceil division), as fg_level_rect in common.glsl.
std::uint32_t level_size(std::uint32_t full, std::uint32_t level) { return (full + (1u << level) - 1) >> level; }

void add_view(FrameGraph& g, int view) {
    std::string name = view_name(view);
    bool centre = view == kCentreView;
    std::uint32_t w = centre ? g.centre_width : g.width, h = centre ? g.centre_height : g.height;
    std::uint32_t levels = std::max(1u, g.settings.cone_levels);
    std::uint32_t atlas_h = h;
    if (levels > 1) {
        std::uint32_t stacked = 0;
        for (std::uint32_t k = 1; k < levels; ++k) stacked += level_size(h, k);
        atlas_h = std::max(h, stacked);
    }
    std::string atlas = "cone." + name;
    g.add_image({atlas, w + (levels > 1 ? level_size(w, 1) : 0), atlas_h, ImageFormat::RG32F,
                 fmt::format("{} conemarch levels (depth, cone bound)", levels)});
    std::string depth = "depth." + name;
    g.add_image({depth, w, h, ImageFormat::R32F, "hit distance or miss"});
    bool glow = g.effects.has(Effect::Glow);
    if (glow) g.add_image({"glow." + name, w, h, ImageFormat::R32F, "closest approach along the ray"});
    // The tail queue: every pixel's room when the tail pass runs.
    std::string queue = "tail." + name;
    bool tail = g.tail_after > 0 && g.manifest_has_tail;
    if (tail) g.add_buffer({queue, 16 + 16ull * w * h, {0, 1, 1, 0}, "pixels whose march continues in the tail pass", {}});
    // Persistent lanes' work queues at full resolution: one word per dispatch (stride 1 and 2).
    std::string lanes = "lanes." + name;
    if (g.persistent_lanes) g.add_buffer({lanes, 8, {0, 0}, "next pixel of each full-resolution dispatch", {}});
    std::string rays = add_rays_buffer(g, view, w, h);
    // Cross-frame reuse reads this eye's levels of the frame before; otherwise the program's binding
    // gets the levels it writes anyway.
    std::string previous_levels = atlas;
    if (g.reuse && view != kCentreView) {
        g.keep_for_next_frame(atlas);
        previous_levels = previous(atlas);
    }
    auto level_pass = [&](std::uint32_t k, int stride) {
        FramePass p;
        p.label = fmt::format("conemarch.{}.L{}", name, k);
        p.program = "conemarch";
        p.timer = "march";
        // Every level binds what the program declares; only level 0 writes the depth, glow and queue.
        p.bind("fg_levels", atlas, k + 1 < levels ? Access::ReadWrite : Access::Write);
        p.bind("fg_depth", depth, Access::Write);
        if (tail) p.bind("FgTail", queue, Access::ReadWrite);
        else p.leave_unused("FgTail");
        if (g.persistent_lanes) p.bind("FgLaneQueue", lanes, Access::ReadWrite);
        else p.leave_unused("FgLaneQueue");
        p.bind("fg_previous_levels", previous_levels, Access::Read);
        if (g.persistent_lanes) p.bind("FgRays", rays, Access::Write);
        else p.leave_unused("FgRays");
        if (glow) p.bind("fg_glow", "glow." + name, Access::Write);
        p.persistent_lanes = k == 0 && g.persistent_lanes;
        p.counter_slot = g.counter_slot(fmt::format("march.L{}", k));
        p.set_push(ConemarchPush{view, static_cast<std::int32_t>(k), k + 1 == levels ? 1 : 0, p.counter_slot, stride});
        // The coarse and the full-resolution march, the centre view's and an eye's, are separate
        // pipelines: one shader would run both cases on a CPU rasteriser.
        p.specialize[kSpecFullResolution.id] = k == 0 ? 1 : 0;
        p.specialize[kSpecCentreView.id] = centre ? 1 : 0;
        return p;
    };
    // A foveated periphery's pixel stands for its 2x2 block, as a level-1 cell does: it starts from
    // level 2, where the pack's shaders can (FG_SPEC_PERIPHERY_PARENT). Level 1 then serves only the
    // pixels short of the periphery and dispatches only the tiles over them. Not with
    // cross-frame reuse, which walks every cell of the old level 1: there level 1 is marched whole,
    // and the periphery starts from it.
    const bool periphery_from_2 = g.foveated(view) && levels > 2 && g.periphery_from_level_2 && !g.reuse;
    for (std::uint32_t k = levels; k-- > 1;) {
        FramePass p = level_pass(k, 1);
        p.invocations = {level_size(w, k), level_size(h, k), 1};
        if (k == 1 && periphery_from_2) g.dispatch_tiles(p, view, TileRegion::FoveaLevel1);
        g.add_pass(std::move(p));
    }
    if (centre) {
        FramePass p = level_pass(0, 1);
        p.invocations = {w, h, 1};
        g.add_pass(std::move(p));
    } else {
        g.add_pixel_pass(view, [&](int stride) {
            FramePass p = level_pass(0, stride);
            if (stride == 2 && periphery_from_2) p.specialize[kSpecPeripheryParent.id] = 2;
            return p;
        });
    }
    if (g.persistent_lanes) add_resolve_pass(g, view, w, h, atlas);
    if (tail) {
        FramePass p;
        p.label = "tail." + name;
        p.program = "tail";
        p.timer = "march";
        p.bind("fg_levels", atlas, Access::ReadWrite);
        p.bind("fg_depth", depth, Access::Write);
        p.bind("FgTail", queue, Access::Read);
        if (glow) p.bind("fg_glow", "glow." + name, Access::Write);
        p.counter_slot = g.counter_slot("tail");
        p.set_push(TailPush{view, p.counter_slot});
        p.indirect = queue;
        g.add_pass(std::move(p));
    }
}

}  // namespace

void add_conemarch_passes(FrameGraph& g) {
    if (g.settings.stereo == StereoMode::Naive) return;
    if (g.settings.stereo == StereoMode::Reproject && !g.is_panorama()) add_view(g, kCentreView);
    else
        for (int view : g.output_views()) add_view(g, view);
}

}  // namespace fg
