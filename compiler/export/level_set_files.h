#pragma once
// Level sets on disk: .vdb files written with the graph's name and parameters as metadata, read
// back, and the shards of one export merged into the whole.
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "common/diagnostics.h"

namespace fg {

// Writes the grid (and its metadata) through a temporary file renamed into place, so a killed
// export leaves no half-written file under the final name.
bool write_level_set(const std::string& path, openvdb::FloatGrid::Ptr grid, Diagnostics& diag);

// The first level set (FloatGrid of class level set) in the file; null with a diagnostic naming
// the file otherwise.
openvdb::FloatGrid::Ptr read_level_set(const std::string& path, Diagnostics& diag);

// The shards' active voxels copied into one grid (they are disjoint), the signs of the voxels
// between them filled again: the grid one whole run writes. The shards must share a voxel size.
openvdb::FloatGrid::Ptr merge_shards(const std::vector<openvdb::FloatGrid::Ptr>& shards,
                                     const std::vector<std::string>& names, Diagnostics& diag);

// Whether a file can be created at path (tried, then removed): to fail before hours of work.
bool can_write(const std::string& path, const std::string& option, Diagnostics& diag);

}  // namespace fg
