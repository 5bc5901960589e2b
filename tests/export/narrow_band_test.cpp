// The sparse narrow band against every voxel of the box sampled densely, and shards merged
// against one whole run, on real graphs through the CPU twin and OpenVDB's own grid and files.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "../compiler/test_support.h"
#include "scratch_dir.h"
#include "export/level_set_files.h"
#include "export/narrow_band_sampler.h"

namespace fg {
namespace {

struct Scene {
    IrGraph ir;
    std::optional<CpuEvaluator> ev;
};

// The IR lives on the heap: the evaluator keeps a pointer to it.
std::unique_ptr<Scene> load(const std::string& relative) {
    Diagnostics diag;
    auto scene = std::make_unique<Scene>();
    auto ir = load_and_lower(test::read_source_file(relative), NodeLibrary::builtin(), diag);
    EXPECT_TRUE(ir) << diag.format();
    scene->ir = std::move(*ir);
    scene->ev = CpuEvaluator::create(scene->ir, diag);
    EXPECT_TRUE(scene->ev) << diag.format();
    return scene;
}

// The sponge cut by a box through its tunnels, so the box's closing faces are in the band too.
ExportField sponge_field(const Scene& s) { return ExportField(*s.ev, 1.0, 0.0, ExportBox{glm::dvec3(-1.1), glm::dvec3(1.1, 1.1, 0.5)}); }

TEST(NarrowBand, skips_no_voxel_of_the_band_and_keeps_none_outside_it) {
    auto scene = load("tests/export/graphs/menger3.json");
    const ExportField field = sponge_field(*scene);
    NarrowBandSettings s;
    s.voxel_size = 2.2 / 48;
    auto grid = sample_narrow_band(field, s);
    const double band = s.half_width * s.voxel_size;
    auto acc = grid->getConstAccessor();
    std::uint64_t in_band = 0;
    for (int i = -30; i <= 30; ++i)
        for (int j = -30; j <= 30; ++j)
            for (int k = -30; k <= 30; ++k) {
                const double d = field(glm::dvec3(i, j, k) * s.voxel_size);
                const openvdb::Coord c(i, j, k);
                ASSERT_EQ(acc.isValueOn(c), std::abs(d) < band) << i << " " << j << " " << k << ": " << d;
                if (std::abs(d) < band) {
                    ++in_band;
                    ASSERT_FLOAT_EQ(acc.getValue(c), static_cast<float>(d));
                } else {
                    ASSERT_EQ(acc.getValue(c) > 0.0f, d > 0.0) << "the sign outside the band, at " << i << " " << j << " " << k;
                }
            }
    EXPECT_EQ(grid->activeVoxelCount(), in_band);
    EXPECT_GT(in_band, 10000u);
}

TEST(NarrowBand, shards_merged_are_the_whole_run_read_back_from_files) {
    auto scene = load("tests/export/graphs/menger3.json");
    const ExportField field = sponge_field(*scene);
    NarrowBandSettings s;
    s.voxel_size = 2.2 / 100;   // four columns of blocks: two each
    auto whole = sample_narrow_band(field, s);
    const test::ScratchDir folder("fg_narrow_band");
    std::vector<openvdb::FloatGrid::Ptr> shards;
    std::vector<std::string> names;
    Diagnostics diag;
    for (int i = 0; i < 2; ++i) {
        s.shard = i;
        s.shards = 2;
        names.push_back((folder / fmt::format("shard{}.vdb", i)).string());
        ASSERT_TRUE(write_level_set(names.back(), sample_narrow_band(field, s), diag)) << diag.format();
        shards.push_back(read_level_set(names.back(), diag));
        ASSERT_TRUE(shards.back()) << diag.format();
        EXPECT_GT(shards.back()->activeVoxelCount(), 0u) << "every slab of the sponge has surface";
    }
    auto merged = merge_shards(shards, names, diag);
    ASSERT_TRUE(merged) << diag.format();
    EXPECT_EQ(merged->activeVoxelCount(), whole->activeVoxelCount());
    EXPECT_EQ(merged->evalActiveVoxelBoundingBox(), whole->evalActiveVoxelBoundingBox());
    auto acc = merged->getConstAccessor();
    for (auto v = whole->cbeginValueOn(); v; ++v) ASSERT_EQ(acc.getValue(v.getCoord()), *v) << v.getCoord();
    // Inactive voxels between the leaves have the sign of their side, as in the whole run.
    auto whole_acc = whole->getConstAccessor();
    for (int i = -56; i <= 56; i += 4)
        for (int j = -56; j <= 56; j += 4)
            for (int k = -56; k <= 56; k += 4) {
                const openvdb::Coord c(i, j, k);
                ASSERT_EQ(acc.getValue(c) > 0.0f, whole_acc.getValue(c) > 0.0f) << c;
            }
}

}  // namespace
}  // namespace fg
