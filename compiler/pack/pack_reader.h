#pragma once
// Reads a .fgpack and refuses anything it cannot trust: wrong magic, newer version, a truncated or
// damaged chunk (xxh64), missing chunks or an inconsistent manifest, each reported with the byte
// offset. Shared by fgc (info) and the runtime.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "chunk_tags.h"
#include "environment_image.h"
#include "common/diagnostics.h"
#include "manifest.h"

namespace fg {

struct PackChunkInfo {
    ChunkTag tag{};
    std::string name;
    std::uint64_t offset = 0;        // of the chunk header
    std::uint64_t payload_size = 0;
    std::uint64_t checksum = 0;
};

struct Pack {
    std::uint16_t version_major = 0, version_minor = 0;
    std::uint64_t file_size = 0;
    PackManifest manifest;
    nlohmann::json manifest_json;
    std::map<std::string, std::vector<std::uint32_t>> spirv;   // pass name -> words
    std::string graph;                                         // source graph JSON text
    nlohmann::json source_map;
    std::map<std::string, std::string> glsl;                   // pass name -> debug GLSL (optional)
    std::optional<EnvironmentImage> environment;               // scene.environment's image, if it has one
    std::vector<PackChunkInfo> chunks;
};

std::optional<Pack> read_pack(std::span<const std::uint8_t> bytes, Diagnostics& diag);
std::optional<Pack> read_pack_file(const std::string& path, Diagnostics& diag);

}  // namespace fg
