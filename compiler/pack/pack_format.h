#pragma once
// Byte layout of a .fgpack (little-endian), shared by writer and reader:
//
//   header (32 bytes)  magic "FGPK" | u16 major | u16 minor | u32 chunk count | u32 reserved (0)
//                      | u64 file size | u64 xxh64 of the preceding 24 bytes
//   chunk (repeated)   tag[4] | u32 name length | u64 payload size | name | payload
//                      | u64 xxh64 of everything of the chunk before it
#include <cstddef>
#include <cstdint>

namespace fg::pack_format {

inline constexpr std::size_t kHeaderSize = 32;
inline constexpr std::size_t kChunkHeaderSize = 16;
inline constexpr std::size_t kChecksumSize = 8;
inline constexpr std::uint32_t kMaxChunks = 4096;
inline constexpr std::uint32_t kMaxNameLength = 64;
inline constexpr std::uint64_t kMaxPayload = 1ull << 30;
inline constexpr std::uint64_t kSeed = 0x46475041434b31ull;  // "FGPACK1"

}  // namespace fg::pack_format
