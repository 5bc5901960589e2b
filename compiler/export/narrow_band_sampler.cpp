#include "narrow_band_sampler.h"

#include <algorithm>
#include <atomic>
#include <bitset>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <openvdb/tools/SignedFloodFill.h>

namespace fg {

namespace {

using Leaf = openvdb::FloatTree::LeafNodeType;
constexpr int kBlock = 32;                 // voxels along a block, the unit of work and of sharding
constexpr int kLeaf = Leaf::DIM;           // 8

// One thread's sampling: its own copy of the field (the CPU twin is not shared across threads)
// and the leaves it filled.
class BlockSampler {
public:
    BlockSampler(const ExportField& field, double voxel_size, double band)
        : field_(field), h_(voxel_size), band_(band) {}

    void block(const openvdb::Coord& origin, int size) {
        if (!may_hold_band(origin, size)) return;
        if (size == kLeaf) return leaf(origin);
        const int half = size / 2;
        for (int i = 0; i < 8; ++i) block(origin.offsetBy(i & 1 ? half : 0, i & 2 ? half : 0, i & 4 ? half : 0), half);
    }

    std::vector<Leaf*>& leaves() { return leaves_; }
    std::uint64_t evaluations() const { return evaluations_; }
    std::uint64_t inside() const { return inside_; }

private:
    double at(double i, double j, double k) {
        ++evaluations_;
        return field_(glm::dvec3(i, j, k) * h_);
    }

    // Whether a block's voxels can hold a value inside the band; the centre's value is kept for
    // the sign of a skipped block inside a leaf.
    bool may_hold_band(const openvdb::Coord& o, int size) {
        const double c = 0.5 * (size - 1);
        last_ = at(o.x() + c, o.y() + c, o.z() + c);
        return std::abs(last_) <= c * std::sqrt(3.0) * h_ + band_;
    }

    void leaf(const openvdb::Coord& origin) {
        std::fill(std::begin(values_), std::end(values_), static_cast<float>(band_));
        any_active_ = false;
        active_.reset();
        inside_leaf(origin, kLeaf / 2);
        if (!any_active_) return;
        auto* leaf = new Leaf(origin, static_cast<float>(band_));
        for (openvdb::Index n = 0; n < Leaf::SIZE; ++n) {
            leaf->setValueOnly(n, values_[n]);
            if (active_.test(n)) leaf->setValueOn(n);
        }
        leaves_.push_back(leaf);
    }

    // The eight sub-blocks of size `size` of a block of twice that size.
    void inside_leaf(const openvdb::Coord& parent, int size) {
        for (int i = 0; i < 8; ++i) {
            openvdb::Coord o = parent.offsetBy(i & 1 ? size : 0, i & 2 ? size : 0, i & 4 ? size : 0);
            if (size == 1) {
                voxel(o, at(o.x(), o.y(), o.z()));
            } else if (may_hold_band(o, size)) {
                inside_leaf(o, size / 2);
            } else {
                fill(o, size, last_ > 0.0 ? band_ : -band_);   // no crossing inside: one sign
            }
        }
    }

    void voxel(const openvdb::Coord& ijk, double d) {
        const openvdb::Index n = Leaf::coordToOffset(ijk);
        values_[n] = static_cast<float>(std::clamp(d, -band_, band_));
        if (std::abs(d) < band_) {
            active_.set(n);
            any_active_ = true;
            inside_ += d < 0.0;
        }
    }

    void fill(const openvdb::Coord& o, int size, double value) {
        for (int x = 0; x < size; ++x)
            for (int y = 0; y < size; ++y)
                for (int z = 0; z < size; ++z) values_[Leaf::coordToOffset(o.offsetBy(x, y, z))] = static_cast<float>(value);
    }

    ExportField field_;
    double h_, band_;
    double last_ = 0.0;
    std::vector<Leaf*> leaves_;
    std::uint64_t evaluations_ = 0, inside_ = 0;
    float values_[Leaf::SIZE];
    std::bitset<Leaf::SIZE> active_;
    bool any_active_ = false;
};

int floor_to_block(double index) { return static_cast<int>(std::floor(index / kBlock)) * kBlock; }

// The block origins of this shard: the box and a margin of the band and a voxel, in slabs of
// whole blocks along the box's longest axis.
std::vector<openvdb::Coord> shard_blocks(const ExportBox& box, const NarrowBandSettings& s) {
    const double margin = std::ceil(s.half_width) + 1.0;
    openvdb::Coord lo, hi;
    for (int a = 0; a < 3; ++a) {
        lo[a] = floor_to_block(std::floor(box.min[a] / s.voxel_size) - margin);
        hi[a] = floor_to_block(std::ceil(box.max[a] / s.voxel_size) + margin);
    }
    const glm::dvec3 size = box.size();
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const long columns = (hi[axis] - lo[axis]) / kBlock + 1;
    const long first = columns * s.shard / s.shards, last = columns * (s.shard + 1) / s.shards;
    std::vector<openvdb::Coord> out;
    for (int x = lo.x(); x <= hi.x(); x += kBlock)
        for (int y = lo.y(); y <= hi.y(); y += kBlock)
            for (int z = lo.z(); z <= hi.z(); z += kBlock) {
                openvdb::Coord o(x, y, z);
                const long column = (o[axis] - lo[axis]) / kBlock;
                if (column >= first && column < last) out.push_back(o);
            }
    return out;
}

}  // namespace

openvdb::FloatGrid::Ptr sample_narrow_band(const ExportField& field, const NarrowBandSettings& s,
                                           const std::function<void(std::size_t, std::size_t)>& progress,
                                           NarrowBandStats* stats) {
    openvdb::initialize();
    const auto start = std::chrono::steady_clock::now();
    const double band = s.half_width * s.voxel_size;
    const std::vector<openvdb::Coord> blocks = shard_blocks(field.box(), s);

    std::atomic<std::size_t> next{0}, done{0};
    std::vector<BlockSampler> samplers;
    const int threads = std::max(1, s.threads);
    samplers.reserve(static_cast<std::size_t>(threads));
    for (int t = 0; t < threads; ++t) samplers.emplace_back(field, s.voxel_size, band);
    std::vector<std::thread> workers;
    for (auto& sampler : samplers)
        workers.emplace_back([&] {
            for (std::size_t i; (i = next++) < blocks.size(); ++done) sampler.block(blocks[i], kBlock);
        });
    // The calling thread reports progress, so the callback needs no locking.
    for (std::size_t reported = SIZE_MAX; reported != blocks.size();) {
        const std::size_t now = done.load();
        if (progress && now != reported) progress(now, blocks.size());
        reported = now;
        if (now != blocks.size()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    for (auto& w : workers) w.join();

    auto grid = openvdb::FloatGrid::create(static_cast<float>(band));
    grid->setTransform(openvdb::math::Transform::createLinearTransform(s.voxel_size));
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    std::uint64_t evaluations = 0, inside = 0;
    for (auto& sampler : samplers) {
        for (Leaf* leaf : sampler.leaves()) grid->tree().addLeaf(leaf);   // the tree owns it now
        evaluations += sampler.evaluations();
        inside += sampler.inside();
    }
    // Inactive voxels and tiles between the leaves take the sign of their side of the surface.
    openvdb::tools::signedFloodFill(grid->tree());
    if (stats) {
        stats->evaluations = evaluations;
        stats->active_voxels = grid->activeVoxelCount();
        stats->inside_voxels = inside;
        stats->leaves = grid->tree().leafCount();
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return grid;
}

}  // namespace fg
