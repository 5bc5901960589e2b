#pragma once
// The accuracy knobs every pack carries as specialization constants, in one place. Pass templates
// never write constant ids: code generation declares these from this table, so the runtime, the
// benchmark and the shaders agree. Node knobs (bias.<node>, iterations.<node>) take ids from
// kFirstNodeKnobId on.
#include <array>
#include <cstdint>
#include <string_view>

#include "value_type.h"

namespace fg {

struct GlobalKnob {
    std::uint32_t id;
    std::string_view name;        // manifest name and `--knob name=value` on the command line
    std::string_view glsl;        // the constant's name in GLSL
    ValueType type;
    double value;                 // default
    double min, max;
    std::string_view doc;
};

// Id 0 is never used: SPIRV-Cross and some tools read it as "no constant".
inline constexpr std::array<GlobalKnob, 22> kGlobalKnobs{{
    {1, "epsilon", "FG_EPSILON", ValueType::Float, 0.5, 0.001, 4.0,
     "hit threshold as a fraction of the pixel's cone radius at the hit distance"},
    {2, "max_steps", "FG_MAX_STEPS", ValueType::Int, 256, 1, 4096,
     "step cap of a full-resolution march (naive tracer, reprojection fix-up)"},
    {3, "step_scale", "FG_STEP_SCALE", ValueType::Float, 1.0, 0.01, 4.0,
     "multiplier on every step; the compiler sets 1 / Lipschitz bound"},
    {4, "normal_taps", "FG_NORMAL_TAPS", ValueType::Int, 4, 4, 6,
     "finite-difference normal: 4 (tetrahedral) or 6 (central) distance evaluations"},
    {5, "count_evaluations", "FG_COUNT_EVALUATIONS", ValueType::Bool, 0, 0, 1,
     "count distance evaluations per pixel into a buffer (off costs nothing)"},
    {6, "cone_steps", "FG_CONE_STEPS", ValueType::Int, 64, 1, 1024,
     "step cap of each coarse conemarch level"},
    {7, "fine_steps", "FG_FINE_STEPS", ValueType::Int, 64, 1, 4096,
     "step cap of the full-resolution conemarch level"},
    {8, "cone_stop", "FG_CONE_STOP", ValueType::Float, 1.5, 1.05, 8.0,
     "a cone stops when the distance falls below this many cone radii: lower gets closer, higher stops sooner"},
    {9, "overrelax", "FG_OVERRELAX", ValueType::Float, 1.0, 1.0, 2.0,
     "over-relaxation factor of the fine march (Keinert et al.), with fallback; 1 is off"},
    {10, "miss_on_step_cap", "FG_MISS_ON_STEP_CAP", ValueType::Bool, 0, 0, 1,
     "a ray that runs out of steps counts as a miss (1) or a hit where it stopped (0)"},
    {11, "reproject_steps", "FG_REPROJECT_STEPS", ValueType::Int, 32, 1, 512,
     "centre-image cells the stereo reprojection walks per level before refining"},
    {12, "reproject_fixup_steps", "FG_FIXUP_STEPS", ValueType::Int, 24, 1, 1024,
     "sphere-tracing steps after reprojection before walking the centre levels again (fix-up march)"},
    {13, "reproject_trust_depth", "FG_REPROJECT_TRUST_DEPTH", ValueType::Bool, 0, 0, 1,
     "reprojection trusts the centre eye's full-resolution hit depth (the seeds' choice: closer, not conservative)"},
    {14, "tail_after", "FG_TAIL_AFTER", ValueType::Int, 0, 0, 4096,
     "full-resolution steps before a still-marching pixel moves to the compacted tail pass; 0 is off"},
    {15, "shade_reuse", "FG_SHADE_REUSE", ValueType::Float, 0.0, 0.0, 16.0,
     "the right eye takes the left eye's shading where both see the same point within this many cone radii "
     "(terms that read the view are recomputed); 0 is off"},
    {16, "persistent_lanes", "FG_PERSISTENT_LANES", ValueType::Bool, 0, 0, 1,
     "full-resolution marching passes hand each SIMD lane the next pixel as soon as its ray ends (same frames)"},
    {17, "reuse", "FG_REUSE", ValueType::Bool, 0, 0, 1,
     "per-eye conemarch starts each cone where the previous frame's levels prove it empty (a static scene)"},
    {18, "shade_history", "FG_SHADE_HISTORY", ValueType::Float, 0.0, 0.0, 8.0,
     "an eye takes the previous frame's shading where it hits the same point within this many cone radii "
     "(a static scene without rim or SSS; terms that read the view are recomputed); 0 is off"},
    {19, "lane_burst", "FG_LANE_BURST", ValueType::Float, 0.875, 0.01, 1.0,
     "persistent lanes march on while this share of a subgroup's lanes has a ray, then refill the idle ones "
     "(lower refills less often; a GPU's wider subgroups may want another share than lavapipe's 8 lanes)"},
    {20, "step_fraction", "FG_STEP_FRACTION", ValueType::Float, 1.0, 0.01, 1.0,
     "each march step advances this fraction of the estimate (already in step_scale) while hit tests read "
     "the whole estimate: shorter steps without a fatter surface (Mandelbulber's DE factor)"},
    {21, "volume_steps", "FG_VOLUME_STEPS", ValueType::Int, 32, 1, 1024,
     "points of a glowing medium (volume_density) evaluated along each eye ray inside the bounds; each costs one "
     "evaluation of the medium's nodes"},
    {22, "reflection_bounces", "FG_REFLECTION_BOUNCES", ValueType::Int, 1, 1, 8,
     "mirror bounces a reflected ray takes (the graph's reflection): where it meets a surface that reflects too, it "
     "reflects again, up to this many; the last surface it meets gets only its direct light"},
}};

inline constexpr std::uint32_t kFirstNodeKnobId = 100;

// Dispatch constants: not knobs, and not in the manifest's list of them. The runtime fixes them per
// pipeline from the frame graph: what a pass would otherwise read from its push constants or the
// frame's uniforms. A CPU rasteriser runs both sides of every branch, uniform ones included
// (docs/accuracy.md), so only a constant known when the pipeline is made drops the code of the
// cases a dispatch never runs. -1, the default, leaves the shader reading the value itself.
struct DispatchConstant {
    std::uint32_t id;
    std::string_view glsl;
    std::string_view doc;
};

inline constexpr DispatchConstant kSpecProjection{60, "FG_SPEC_PROJECTION", "the frame's projection (fg_frame.projection)"};
inline constexpr DispatchConstant kSpecCentreView{61, "FG_SPEC_CENTRE_VIEW", "1: the pass marches the centre view, 0: an eye"};
inline constexpr DispatchConstant kSpecFullResolution{62, "FG_SPEC_FULL_RESOLUTION",
                                                      "1: conemarch level 0, 0: a coarse level"};
// 63 was FG_SPEC_FOVEA_WINDOW (a square window around the fovea), which the tile lists replaced.
inline constexpr DispatchConstant kSpecPeripheryParent{
    64, "FG_SPEC_PERIPHERY_PARENT", "the conemarch level a foveated periphery's pixel starts from (-1: level 1)"};
inline constexpr DispatchConstant kSpecTileList{
    65, "FG_SPEC_TILE_LIST", "1: the pass dispatches the 8x8 tiles its FgTiles buffer lists, not a grid over its image"};
// Whether the frames may hold a lens or a fovea at all: without them, every pass drops the per-pixel
// tests for them (a quarter of the shade pass's own cost on lavapipe, which runs the test's code
// whether or not a frame has a lens).
inline constexpr DispatchConstant kSpecLens{66, "FG_SPEC_LENS", "0: no frame has a lens mask (fg_outside_lens is false), 1: frames may"};
inline constexpr DispatchConstant kSpecFoveated{67, "FG_SPEC_FOVEATED", "0: the frame graph is not foveated (fg_periphery is 0), 1: it is"};
inline constexpr std::array<DispatchConstant, 7> kDispatchConstants{kSpecProjection, kSpecCentreView, kSpecFullResolution,
                                                                    kSpecPeripheryParent, kSpecTileList, kSpecLens, kSpecFoveated};
static_assert(kGlobalKnobs.back().id < kSpecProjection.id, "global knob ids would run into the dispatch constants'");

inline bool is_dispatch_constant(std::uint32_t id) {
    for (const auto& c : kDispatchConstants)
        if (c.id == id) return true;
    return false;
}

inline const GlobalKnob* find_global_knob(std::string_view name) {
    for (const auto& k : kGlobalKnobs)
        if (k.name == name) return &k;
    return nullptr;
}

}  // namespace fg
