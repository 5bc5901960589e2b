#include "signed_band.h"

#include <cmath>

#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/task_arena.h>

namespace fg {

void make_signed_band(openvdb::FloatGrid& grid, double half_width, int threads) {
    if (grid.activeVoxelCount() == 0) return;
    const float band = static_cast<float>(half_width * grid.voxelSize()[0]);
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
