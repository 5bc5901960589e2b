#pragma once
// What an export will cost, told before it starts: two pilot runs at coarse resolutions (32 and 64
// voxels along the box's longest side, well under a second for the gallery) measure how the
// narrow band grows as voxels shrink, N ~ (1 / voxel size)^D with D between 2 (a smooth surface)
// and 3 (a surface that fills space), and extrapolate voxels, memory and time to the target.
#include "export_field.h"
#include "narrow_band_sampler.h"

namespace fg {

struct ExportEstimate {
    // Doubles: a voxel size far too small for any machine must still give a number to refuse.
    double active_voxels = 0.0;
    double leaves = 0.0;
    double bytes = 0.0;           // peak memory of the process
    double seconds = 0.0;         // sampling time with the target's threads
    double dimension = 2.0;       // the measured growth exponent D
    // Whether the distance goes negative (inside the shape). Many fractals' estimates measure the
    // distance to the set and never do: they have no zero crossing to mesh.
    bool has_inside = false;
};

ExportEstimate estimate_export(const ExportField& field, const NarrowBandSettings& target, bool mesh);

}  // namespace fg
