#include "signed_band.h"

#include <cmath>

#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/task_arena.h>

namespace fg {

namespace {

// Turns off the active voxels farther than the band from every sign change (a face neighbour of
// the other sign): the sampled interior slab of a fractal is most of the band, and the sweep
// costs memory per active voxel. What stays is the band and a voxel, by the cube around each
// crossing voxel (which holds the ball of the band's radius).
void keep_near_crossings(openvdb::FloatGrid& grid, double half_width) {
    openvdb::MaskTree near;
    const auto values = grid.getConstAccessor();
    for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf)
        for (auto v = leaf->cbeginValueOn(); v; ++v) {
            const openvdb::Coord c = v.getCoord();
            const bool inside = *v < 0.0f;
            for (int axis = 0; axis < 3; ++axis)
                for (int step : {-1, 1}) {
                    openvdb::Coord n = c;
                    n[axis] += step;
                    if ((values.getValue(n) < 0.0f) != inside) near.setValueOn(c);
                }
        }
    openvdb::tools::dilateActiveValues(near, static_cast<int>(std::ceil(half_width)) + 1,
                                       openvdb::tools::NN_FACE_EDGE_VERTEX, openvdb::tools::IGNORE_TILES);
    grid.tree().topologyIntersection(near);
}

}  // namespace

void make_signed_band(openvdb::FloatGrid& grid, double half_width, int threads) {
    if (grid.activeVoxelCount() == 0) return;
    const float band = static_cast<float>(half_width * grid.voxelSize()[0]);
    keep_near_crossings(grid, half_width);
    openvdb::FloatGrid::Ptr swept;
    tbb::task_arena(std::max(1, threads)).execute([&] { swept = openvdb::tools::sdfToSdf(grid, 0.0f); });
    auto& tree = swept->tree();
    for (auto leaf = tree.beginLeaf(); leaf; ++leaf)
        for (auto v = leaf->beginValueOn(); v; ++v)
            if (!(std::abs(*v) < band)) {   // beyond the band (or an unreached voxel at +-inf)
                const float side = *v < 0.0f ? -band : band;
                v.setValue(side);
                v.setValueOff();
            }
    openvdb::tools::changeLevelSetBackground(tree, band);
    openvdb::tools::pruneLevelSet(tree);
    openvdb::tools::signedFloodFill(tree);
    grid.setTree(swept->treePtr());
}

}  // namespace fg
