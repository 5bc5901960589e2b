#include "pack_writer.h"

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <xxhash.h>

#include <unistd.h>

#include "pack_format.h"

namespace fg {

namespace {
void put(std::vector<std::uint8_t>& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}
}  // namespace

std::vector<std::uint8_t> PackWriter::bytes() const {
    using namespace pack_format;
    std::vector<std::uint8_t> out;
    out.insert(out.end(), kPackMagic.begin(), kPackMagic.end());
    put(out, kPackVersionMajor, 2);
    put(out, kPackVersionMinor, 2);
    put(out, chunks_.size(), 4);
    put(out, 0, 4);
    put(out, 0, 8);  // file size, patched below
    put(out, 0, 8);  // header checksum, patched below
    for (const auto& chunk : chunks_) {
        std::size_t start = out.size();
        auto tag = chunk->tag();
        auto name = chunk->name();
        auto payload = chunk->payload();
        out.insert(out.end(), tag.begin(), tag.end());
        put(out, name.size(), 4);
        put(out, payload.size(), 8);
        out.insert(out.end(), name.begin(), name.end());
        out.insert(out.end(), payload.begin(), payload.end());
        put(out, XXH64(out.data() + start, out.size() - start, kSeed), 8);
    }
    std::uint64_t size = out.size();
    for (int i = 0; i < 8; ++i) out[16 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(size >> (8 * i));
    std::uint64_t header_hash = XXH64(out.data(), 24, kSeed);
    for (int i = 0; i < 8; ++i)
        out[24 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(header_hash >> (8 * i));
    return out;
}

bool PackWriter::write_file(const std::string& path, Diagnostics& diag) const {
    return write_file_atomically(path, bytes(), diag);
}

bool write_file_atomically(const std::string& path, const std::vector<std::uint8_t>& data, Diagnostics& diag) {
    // A temporary name of this process and call alone: two writers of one file never share it.
    static std::atomic<unsigned> calls{0};
    const std::string tmp = fmt::format("{}.tmp{}-{}", path, ::getpid(), calls++);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            diag.error(fmt::format("cannot write {}", tmp));
            return false;
        }
        out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
        if (!out) {
            diag.error(fmt::format("writing {} failed (disk full?)", tmp));
            return false;
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        diag.error(fmt::format("cannot move {} to {}: {}", tmp, path, ec.message()));
        std::filesystem::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace fg
