#pragma once
// Writes a .fgpack: header, then each chunk as tag, name, payload and an xxh64 checksum.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/atomic_file.h"
#include "common/diagnostics.h"
#include "pack_chunk.h"

namespace fg {

class PackWriter {
public:
    void add(std::unique_ptr<PackChunk> chunk) { chunks_.push_back(std::move(chunk)); }
    std::vector<std::uint8_t> bytes() const;
    // Writes atomically (temporary file + rename) so a failed write never leaves half a pack.
    bool write_file(const std::string& path, Diagnostics& diag) const;

private:
    std::vector<std::unique_ptr<PackChunk>> chunks_;
};

}  // namespace fg
