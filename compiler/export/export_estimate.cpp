#include "export_estimate.h"

#include <algorithm>
#include <cmath>

namespace fg {

namespace {
// Measured with /usr/bin/time -v on the gallery's Mandelbulb (docs/export.md): the process
// without the grid, and what each leaf of the grid costs with and without meshing it.
constexpr double kBaseBytes = 48.0 * 1024 * 1024;
constexpr double kLeafBytes = sizeof(openvdb::FloatTree::LeafNodeType) + 256.0;
constexpr double kMeshFactor = 3.0;
}  // namespace

ExportEstimate estimate_export(const ExportField& field, const NarrowBandSettings& target, bool mesh) {
    const glm::dvec3 size = field.box().size();
    const double longest = std::max(size.x, std::max(size.y, size.z));
    NarrowBandSettings fine = target, coarse = target;
    fine.shard = coarse.shard = 0;
    fine.shards = coarse.shards = 1;
    fine.voxel_size = std::max(target.voxel_size, longest / 64.0);
    coarse.voxel_size = 2.0 * fine.voxel_size;
    NarrowBandStats a, b;
    sample_narrow_band(field, coarse, {}, &a);
    sample_narrow_band(field, fine, {}, &b);

    ExportEstimate e;
    e.dimension = a.active_voxels > 0 && b.active_voxels > 0
                      ? std::clamp(std::log2(static_cast<double>(b.active_voxels) / static_cast<double>(a.active_voxels)), 2.0, 3.0)
                      : 2.0;
    const double growth = std::pow(fine.voxel_size / target.voxel_size, e.dimension) / target.shards;
    e.active_voxels = static_cast<double>(b.active_voxels) * growth;
    e.leaves = static_cast<double>(b.leaves) * growth;
    e.bytes = kBaseBytes + e.leaves * kLeafBytes * (mesh ? kMeshFactor : 1.0);
    e.seconds = b.seconds * growth;
    // At least 1 % of the band inside: a solid's band is about half inside, the thinnest gallery
    // fractal's 6 %; an estimate without inside still rounds below zero at a few voxels.
    e.has_inside = static_cast<double>(a.inside_voxels + b.inside_voxels) >= 0.01 * static_cast<double>(a.active_voxels + b.active_voxels);
    return e;
}

}  // namespace fg
