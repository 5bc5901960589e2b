#pragma once
// The sampled band made a true signed distance on both sides of the surface. A fractal's estimate
// is a distance only outside: inside the set it stays near zero (a Mandelbulb's) or was moved out
// by half a voxel (a Mandelbox's, surface_rule.h), so the interior is a slab of values just under
// zero, never the band's depth. OpenVDB's fast sweeping solves the eikonal equation |grad d| = 1
// from the sampled zero crossing over the active voxels (the estimate never overestimates, so they
// hold the whole true band), after the voxels farther than the band from every sampled crossing
// are turned off (the sweep's memory follows its active voxels); voxels it finds beyond the band
// are set to the band's value and turned off, and inactive space takes its side's sign. The
// surface stays where it was sampled.
#include <openvdb/openvdb.h>

namespace fg {

// half_width: the band's half-width in voxels; threads: TBB's workers for the sweeps.
void make_signed_band(openvdb::FloatGrid& grid, double half_width, int threads);

}  // namespace fg
