#pragma once
// What an export will cost, told before it starts. Pilot runs at 32, 64 and 128 voxels along the
// box's longest side (about a second for the gallery) measure how the narrow band grows as voxels
// halve: by 2^D, with D 2 for a smooth surface and up to 3 for one that fills space. A fractal's
// D grows with resolution as finer detail appears, so each further halving to the target takes
// the last D plus its last increase (at most 3): voxels, memory and time follow.
#include "export_field.h"
#include "narrow_band_sampler.h"

namespace fg {

struct ExportEstimate {
    // Doubles: a voxel size far too small for any machine must still give a number to refuse.
    double active_voxels = 0.0;
    double leaves = 0.0;
    double bytes = 0.0;           // peak memory of the process
    double seconds = 0.0;         // sampling time with the target's threads
    double dimension = 2.0;       // D over the last pilot halving
};

ExportEstimate estimate_export(const ExportField& field, const NarrowBandSettings& target, bool mesh);

}  // namespace fg
