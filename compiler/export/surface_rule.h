#pragma once
// Where an export puts the surface of each part of a graph. A part is a node whose distance feeds
// the scene's distance and that reads no other node's distance: a fractal, a primitive. A part
// whose estimate has an inside (negative within the shape) is cut at zero. One without an inside
// measures the distance to its set and never goes below zero (the Mandelbox's |z| / dr): it is
// taken where it falls under half a voxel, as the renderer's hit threshold takes it under a
// pixel's footprint. Each part keeps its own rule, so a union of both kinds keeps both shapes.
#include <string>
#include <vector>

#include "export_field.h"

namespace fg {

struct ExportPart {
    int node = -1;              // IR node index
    std::string id;             // the graph's node id
    double inside_share = 0.0;  // share of the part's narrow band below zero
    // Under 1 % negative is rounding at a few voxels, not an inside: a solid's band is about half
    // inside, the thinnest gallery fractal's 6 %.
    bool has_inside() const { return inside_share >= 0.01; }
};

// The parts of the scene's distance, each sampled alone on a pilot band (128 voxels across the
// box, or the export's own voxels when coarser) to tell whether it has an inside.
std::vector<ExportPart> export_parts(const CpuEvaluator& scene, double scale, const ExportBox& box,
                                     double voxel_size, int threads);

// The scene's evaluator with every part without an inside moved out by `offset` (in the export
// field's units, after `scale`).
CpuEvaluator with_surface_rules(CpuEvaluator scene, const std::vector<ExportPart>& parts, double scale, double offset);

// What fgc export samples: the graph's estimate made a conservative distance (times its step
// factor over its Lipschitz bound, as the march steps), each part by its rule at half a voxel,
// then moved out by `offset` and cut by the box. `parts` receives the parts found.
ExportField export_surface_field(const CpuEvaluator& scene, const ExportBox& box, double voxel_size, double offset,
                                 int threads, std::vector<ExportPart>& parts, Diagnostics& diag);

}  // namespace fg
