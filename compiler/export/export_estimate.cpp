#include "export_estimate.h"

#include <algorithm>
#include <cmath>

namespace fg {

namespace {
// Measured with /usr/bin/time -v on the gallery's Mandelbulb at 256 and 512 voxels across
// (docs/export.md), with a margin: the process without the grid, what each sampled leaf of 8^3
// voxels costs through the sweep that makes the band signed (the grid, OpenVDB's copy of it and
// its sweep masks), and what meshing needs on top (OpenVDB's mesher, positions, normals, triangles).
constexpr double kBaseBytes = 96.0 * 1024 * 1024;
constexpr double kLeafBytes = 8.0 * 1024;
constexpr double kMeshBytesPerLeaf = 1.0 * 1024;
// A shard is not swept (its merge is): its leaves cost what OpenVDB's float leaf holds, its 512
// values on the heap outside sizeof.
constexpr double kSampledLeafBytes = sizeof(openvdb::FloatTree::LeafNodeType) + openvdb::FloatTree::LeafNodeType::SIZE * sizeof(float) + 64.0;

// How much a count (voxels, leaves) measured at three halvings of the voxel grows over `halvings`
// more: each by 2^D, D the last pilots' exponent plus its last rise, between 2 and 3. d: the last D.
double extrapolate(const std::uint64_t (&n)[3], double halvings, double* d_out = nullptr) {
    auto exponent = [](std::uint64_t coarse, std::uint64_t fine) {
        return coarse && fine ? std::clamp(std::log2(static_cast<double>(fine) / static_cast<double>(coarse)), 2.0, 3.0) : 2.0;
    };
    double d = exponent(n[1], n[2]);
    const double rise = std::max(0.0, d - exponent(n[0], n[1]));
    double growth = 1.0;
    for (; halvings > 0.0; halvings -= 1.0) {
        d = std::min(3.0, d + rise);
        growth *= std::exp2(d * std::min(1.0, halvings));
    }
    if (d_out) *d_out = d;
    return growth;
}
}  // namespace

ExportEstimate estimate_export(const ExportField& field, const NarrowBandSettings& target, bool mesh) {
    const glm::dvec3 size = field.box().size();
    const double longest = std::max(size.x, std::max(size.y, size.z));
    NarrowBandStats pilots[3];
    NarrowBandSettings pilot = target;
    pilot.shard = 0;
    pilot.shards = 1;
    // Never finer than the target: a small export is its own pilot.
    const double finest = std::max(target.voxel_size, longest / 128.0);
    for (int i = 0; i < 3; ++i) {
        pilot.voxel_size = finest * std::ldexp(1.0, 2 - i);
        sample_narrow_band(field, pilot, {}, &pilots[i]);
    }
    const NarrowBandStats& last = pilots[2];
    const double halvings = std::log2(finest / target.voxel_size);
    ExportEstimate e;
    const double voxels = extrapolate({pilots[0].active_voxels, pilots[1].active_voxels, last.active_voxels}, halvings, &e.dimension);
    const double leaves = extrapolate({pilots[0].leaves, pilots[1].leaves, last.leaves}, halvings);
    e.active_voxels = static_cast<double>(last.active_voxels) * voxels / target.shards;
    e.leaves = static_cast<double>(last.leaves) * leaves / target.shards;
    const bool swept = target.shards == 1 || mesh;
    e.bytes = kBaseBytes + e.leaves * (swept ? kLeafBytes + (mesh ? kMeshBytesPerLeaf : 0.0) : kSampledLeafBytes);
    e.seconds = last.seconds * voxels / target.shards;
    return e;
}

}  // namespace fg
