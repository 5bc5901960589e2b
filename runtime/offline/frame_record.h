#pragma once
// What makes a rendered frame "done" for --resume: beside each image a small record
// (frame_000042.png.xxh) with the image's XXH3-64 and the job's fingerprint (pack, path and
// settings). A frame counts as done only if both exist, the fingerprint matches and the image's
// bytes still hash to the record, so a half-written file, a frame of another pack or settings,
// or a corrupted copy on shared storage is rendered again. Files appear by rename, so a task
// killed mid-write leaves no image that passes.
#include <cstdint>
#include <span>
#include <string>

namespace fg {

std::uint64_t content_hash(std::span<const std::uint8_t> bytes);
std::string hex64(std::uint64_t h);
// XXH3-64 of a file's bytes; false if it cannot be read.
bool hash_file(const std::string& path, std::uint64_t& out);

std::string frame_record_path(const std::string& image_path);
bool frame_is_done(const std::string& image_path, const std::string& job);
// Writes the image bytes and then its record, each through a temporary file and a rename.
bool write_frame_atomically(const std::string& image_path, std::span<const std::uint8_t> image_bytes, int frame,
                            const std::string& job);

}  // namespace fg
