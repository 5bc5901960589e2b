#pragma once
// Samples an ExportField into an OpenVDB level set on a sparse narrow band: blocks of voxels are
// tested at their centre and skipped when the distance there exceeds the block's half-diagonal
// plus the band (the field never overestimates, so nothing inside can be near the surface); the
// rest are split in eight, down to single voxels. Work and memory follow the band, not the box.
#include <cstdint>
#include <functional>

#include <openvdb/openvdb.h>

#include "export_field.h"

namespace fg {

struct NarrowBandSettings {
    double voxel_size = 0.01;
    double half_width = 3.0;   // voxels each side of the surface (OpenVDB's default band)
    int threads = 2;
    // This shard of the box: slab `shard` of `shards` along its longest axis, whole blocks each,
    // so that the shards' voxels are disjoint and together exactly those of one whole run.
    int shard = 0, shards = 1;
};

struct NarrowBandStats {
    std::uint64_t evaluations = 0;
    std::uint64_t active_voxels = 0;
    std::uint64_t inside_voxels = 0;      // active voxels with a negative distance
    std::uint64_t leaves = 0;
    double seconds = 0.0;
};

// Voxel (i, j, k) lies at world (i, j, k) * voxel_size for every box and shard, so shards and
// runs over different boxes share one lattice. progress(done, total) counts blocks and is called
// from the calling thread only.
openvdb::FloatGrid::Ptr sample_narrow_band(const ExportField& field, const NarrowBandSettings& settings,
                                           const std::function<void(std::size_t, std::size_t)>& progress = {},
                                           NarrowBandStats* stats = nullptr);

}  // namespace fg
