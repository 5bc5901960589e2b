#pragma once
// Whether a float scene's coordinates are too large for float.
//
// The march works where the camera is, around the bounds and at the shapes translated into them;
// float positions there are spaced s = 2^(floor(log2 |p|) - 23) apart. The image holds while s stays
// under a quarter of the hit threshold at the distance the camera views (epsilon times a pixel's
// cone radius, for a headset's 2000 pixels across the camera's field of view) and under 1/4096 of
// the bounds radius. Beyond either, surfaces dissolve into noise where the double build renders
// them: fgc check and compile warn and suggest "precision": "double".
#include <string>

#include "common/diagnostics.h"
#include "ir/ir_graph.h"

namespace fg {

struct PrecisionAdvice {
    double magnitude = 0.0;        // the largest coordinate the march works at
    std::string where;             // JSON pointer it comes from
    std::string node_id;           // a translation's node, when it is one
    double spacing = 0.0;          // of floats at that magnitude
    double viewing_distance = 0.0; // camera to target
    double hit_threshold = 0.0;    // at the viewing distance
    double bounds_radius = 0.0;
    bool too_coarse = false;
};

inline constexpr double kAdvicePixelsAcross = 2000.0;
inline constexpr double kMaxSpacingPerHitThreshold = 0.25;
inline constexpr double kMaxSpacingPerBoundsRadius = 1.0 / 4096.0;

// The spacing of floats (one unit in the last place) at |x|.
double float_spacing(double x);

PrecisionAdvice float_precision_advice(const IrGraph& ir);

// A warning at the largest coordinate when a float scene's spacing is too coarse; nothing for
// double scenes.
void advise_precision(const IrGraph& ir, Diagnostics& diag);

}  // namespace fg
