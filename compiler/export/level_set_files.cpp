#include "level_set_files.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/SignedFloodFill.h>

namespace fg {

bool write_level_set(const std::string& path, openvdb::FloatGrid::Ptr grid, Diagnostics& diag) {
    const std::string temporary = path + ".partial";
    try {
        openvdb::io::File file(temporary);
        file.write({grid});
        file.close();
        std::filesystem::rename(temporary, path);
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        diag.error(fmt::format("cannot write {}: {}", path, e.what()));
        return false;
    }
    return true;
}

openvdb::FloatGrid::Ptr read_level_set(const std::string& path, Diagnostics& diag) {
    openvdb::initialize();
    try {
        openvdb::io::File file(path);
        file.open();
        openvdb::GridPtrVecPtr grids = file.getGrids();
        file.close();
        for (const auto& base : *grids) {
            auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
            if (grid && grid->getGridClass() == openvdb::GRID_LEVEL_SET) return grid;
        }
        diag.error(fmt::format("{}: no level set (a float grid of class level set) in the file", path));
    } catch (const std::exception& e) {
        diag.error(fmt::format("cannot read {}: {}", path, e.what()));
    }
    return nullptr;
}

openvdb::FloatGrid::Ptr merge_shards(const std::vector<openvdb::FloatGrid::Ptr>& shards,
                                     const std::vector<std::string>& names, Diagnostics& diag) {
    if (shards.empty()) return nullptr;
    auto whole = shards.front()->deepCopy();
    for (std::size_t i = 1; i < shards.size(); ++i) {
        if (shards[i]->transform() != whole->transform()) {
            diag.error(fmt::format("{}: voxel size {:g} differs from {}'s {:g}: shards of one export share it", names[i],
                                   shards[i]->voxelSize()[0], names[0], whole->voxelSize()[0]));
            return nullptr;
        }
        auto copy = shards[i]->deepCopy();
        openvdb::tools::compReplace(*whole, *copy);
    }
    openvdb::tools::signedFloodFill(whole->tree());
    whole->removeMeta("fractograph.shard");
    return whole;
}

bool can_write(const std::string& path, const std::string& option, Diagnostics& diag) {
    const bool existed = std::filesystem::exists(path);
    {
        std::ofstream probe(path, std::ios::binary | std::ios::app);
        if (probe) {
            probe.close();
            if (!existed) std::filesystem::remove(path);
            return true;
        }
    }
    diag.error(fmt::format("{} {}: cannot write there: {}", option, path, std::strerror(errno)));
    return false;
}

}  // namespace fg
