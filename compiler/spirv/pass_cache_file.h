#pragma once
// Compiled passes kept on disk between runs, one file per pass named by its cache key in hex: a
// later `fgc compile` of the graph (or of another graph that shares passes) reads the SPIR-V
// instead of running glslang and the optimiser. A file is only a hint: one that is damaged,
// truncated or written for another key is ignored (and replaced by the next compile of its pass).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fg {

// $FG_PASS_CACHE (a folder; "off" disables it), else $XDG_CACHE_HOME/fractograph/passes, else
// ~/.cache/fractograph/passes. Empty when disabled or there is no home.
std::filesystem::path user_pass_cache_folder();

// What decides a pass's SPIR-V besides its GLSL: fgc's version, glslang's and SPIRV-Tools'
// versions and the executable's GNU build id, so that a rebuilt fgc never reads an older one's
// passes. Empty when the executable has no build id.
const std::string& toolchain_id();

std::filesystem::path pass_file(const std::filesystem::path& folder, std::uint64_t key);

// The file's SPIR-V when its magic, format, key, length and checksum are right, else nothing.
std::optional<std::vector<std::uint32_t>> read_pass_file(const std::filesystem::path& file, std::uint64_t key);

// Through a temporary file and a rename, so that processes compiling at once never read half a
// file. False when it could not be written.
bool write_pass_file(const std::filesystem::path& file, std::uint64_t key, std::span<const std::uint32_t> spirv);

// Removes the files written or read longest ago until the folder holds at most `max_bytes`.
void trim_pass_folder(const std::filesystem::path& folder, std::uintmax_t max_bytes);

}  // namespace fg
