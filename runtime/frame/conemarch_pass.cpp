// Progressive cone marching in the frame graph (shader: shaders/conemarch.comp): one dispatch per
// level, coarse to fine, into one atlas image per view; level 0 also writes the view's depth.
#include <fmt/format.h>

#include "frame_graph.h"

namespace fg {

namespace {
// Size of a level (ceil division), as fg_level_rect in common.glsl.
std::uint32_t level_size(std::uint32_t full, std::uint32_t level) { return (full + (1u << level) - 1) >> level; }
}  // namespace

void add_conemarch_passes(FrameGraph& g, int view) {
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
    std::int32_t slot = 0;
    // The tail queue: big enough for every pixel when the tail pass runs, a stub otherwise (the
    // program declares it either way).
    std::string queue = "tail." + name;
    bool tail = g.tail_after > 0 && g.manifest_has_tail;
    g.add_buffer({queue, tail ? 16 + 16ull * w * h : 32, {0, 1, 1, 0},
                  tail ? "pixels whose march continues in the tail pass" : "(tail pass off)"});
    for (std::uint32_t k = levels; k-- > 0;) {
        FramePass p;
        p.label = fmt::format("conemarch.{}.L{}", name, k);
        p.program = "conemarch";
        p.timer = "march";
        // Every level binds what the program declares; only level 0 writes the depth and glow.
        p.bindings = {{"fg_levels", atlas}, {"fg_depth", depth}, {"FgTail", queue}};
        if (glow) p.bindings.push_back({"fg_glow", "glow." + name});
        p.writes = {atlas};
        if (k + 1 < levels) p.reads = {atlas};
        if (k == 0) {
            p.writes.push_back(depth);
            if (glow) p.writes.push_back("glow." + name);
        }
        p.counter_slot = slot = g.counter_slot(fmt::format("march.L{}", k));
        p.push = {view, static_cast<std::int32_t>(k), k + 1 == levels ? 1 : 0, slot};
        p.groups[0] = (level_size(w, k) + 7) / 8;
        p.groups[1] = (level_size(h, k) + 7) / 8;
        if (k == 0 && tail) p.writes.push_back(queue);
        if (k == 0) {
            g.add_pixel_pass(std::move(p), view);
        } else {
            p.push.push_back(1);
            g.add_pass(std::move(p));
        }
    }
    if (tail) {
        FramePass p;
        p.label = "tail." + name;
        p.program = "tail";
        p.timer = "march";
        p.bindings = {{"fg_levels", atlas}, {"fg_depth", depth}, {"FgTail", queue}};
        if (glow) p.bindings.push_back({"fg_glow", "glow." + name});
        p.reads = {queue, atlas};
        p.writes = {atlas, depth};
        if (glow) p.writes.push_back("glow." + name);
        p.counter_slot = g.counter_slot("tail");
        p.push = {view, p.counter_slot};
        p.indirect = queue;
        g.add_pass(std::move(p));
    }
}

}  // namespace fg
