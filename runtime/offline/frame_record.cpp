#include "frame_record.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <vector>
#include <xxhash.h>

#include "common/atomic_file.h"

namespace fg {

namespace {
// Unique per host and process (write_file_atomically): tasks given overlapping ranges never share
// a temporary.
bool write_then_rename(const std::string& path, std::span<const std::uint8_t> bytes) {
    Diagnostics ignored;   // the caller says which frame could not be written
    return write_file_atomically(path, bytes, ignored);
}
}  // namespace

std::uint64_t content_hash(std::span<const std::uint8_t> bytes) { return XXH3_64bits(bytes.data(), bytes.size()); }

std::string hex64(std::uint64_t h) { return fmt::format("{:016x}", h); }

bool hash_file(const std::string& path, std::uint64_t& out) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    out = content_hash(bytes);
    return true;
}

std::string frame_record_path(const std::string& image_path) { return image_path + ".xxh"; }

bool frame_is_done(const std::string& image_path, const std::string& job) {
    std::ifstream f(frame_record_path(image_path));
    if (!f) return false;
    nlohmann::json record = nlohmann::json::parse(f, nullptr, false);
    if (record.is_discarded() || !record.is_object() || record.value("job", "") != job) return false;
    std::uint64_t h = 0;
    return hash_file(image_path, h) && record.value("xxh3", "") == hex64(h);
}

bool write_frame_atomically(const std::string& image_path, std::span<const std::uint8_t> image_bytes, int frame,
                            const std::string& job) {
    if (!write_then_rename(image_path, image_bytes)) return false;
    nlohmann::json record = {{"frame", frame}, {"xxh3", hex64(content_hash(image_bytes))}, {"job", job}};
    std::string text = record.dump() + "\n";
    return write_then_rename(frame_record_path(image_path),
                             {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

}  // namespace fg
