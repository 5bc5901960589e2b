// libFuzzer target: any bytes, read as a .fgpack, must give a pack or an error naming a byte offset,
// never a crash, a sanitizer report or an exception (the runtime opens packs it did not write).
//
// Almost every mutation of a pack breaks an xxh64 checksum, so the raw input alone would only ever
// exercise the framing. Each input is therefore read twice: as it is, and "resealed" (the header and
// every chunk checksum recomputed the way the writer would, the file size made to match), which lets mutated manifests, chunk
// lists and payloads reach the manifest parser and the consistency checks.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <span>
#include <vector>

#include <xxhash.h>

#include "pack/pack_format.h"
#include "pack/pack_reader.h"

namespace {

using namespace fg::pack_format;

std::uint64_t get(const std::vector<std::uint8_t>& b, std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(b[at + static_cast<std::size_t>(i)]) << (8 * i);
    return v;
}
void put(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

// Sets the header's file size to the real one and recomputes the checksums of whatever chunks fit; leaves everything else as the fuzzer made it.
void reseal(std::vector<std::uint8_t>& b) {
    if (b.size() < kHeaderSize) return;
    put(b, 16, b.size());
    put(b, 24, XXH64(b.data(), 24, kSeed));
    std::uint64_t count = get(b, 8, 4);
    std::size_t at = kHeaderSize;
    for (std::uint64_t i = 0; i < count && i < kMaxChunks; ++i) {
        if (b.size() - at < kChunkHeaderSize) return;
        std::uint64_t name_len = get(b, at + 4, 4), payload = get(b, at + 8, 8);
        if (name_len > kMaxNameLength || payload > kMaxPayload) return;
        std::uint64_t total = kChunkHeaderSize + name_len + payload + kChecksumSize;
        if (total > b.size() - at) return;
        std::size_t checksum_at = at + static_cast<std::size_t>(total) - kChecksumSize;
        put(b, checksum_at, XXH64(b.data() + at, checksum_at - at, kSeed));
        at += static_cast<std::size_t>(total);
    }
}

void read(std::span<const std::uint8_t> bytes) {
    try {
        fg::Diagnostics diag;
        auto pack = fg::read_pack(bytes, diag);
        if (!pack) {
            bool located = false;
            for (const auto& d : diag.items()) located |= d.severity == fg::Severity::Error && d.byte.has_value();
            if (!located) {
                std::fprintf(stderr, "read_pack refused the input without an error naming a byte:\n%s\n",
                             diag.format().c_str());
                std::abort();
            }
        } else if (diag.has_errors()) {
            std::fprintf(stderr, "read_pack accepted the input but reported errors:\n%s\n", diag.format().c_str());
            std::abort();
        }
        (void)diag.format();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "read_pack threw: %s\n", e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "read_pack threw a non-std exception\n");
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    read(std::span<const std::uint8_t>(data, size));
    std::vector<std::uint8_t> sealed(data, data + size);
    reseal(sealed);
    read(sealed);
    return 0;
}
