#include "pack_writer.h"

#include <xxhash.h>

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

}  // namespace fg
