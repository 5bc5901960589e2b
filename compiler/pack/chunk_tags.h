#pragma once
// The chunk tags of a .fgpack, in one place (docs/pack-format.md describes the layout).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace fg {

using ChunkTag = std::array<char, 4>;

inline constexpr ChunkTag kTagManifest{'M', 'A', 'N', 'I'};   // manifest JSON
inline constexpr ChunkTag kTagSpirv{'S', 'P', 'R', 'V'};      // SPIR-V of one pass (name = pass)
inline constexpr ChunkTag kTagGraph{'G', 'R', 'P', 'H'};      // the source graph JSON
inline constexpr ChunkTag kTagSourceMap{'S', 'M', 'A', 'P'};  // generated GLSL line -> graph node
inline constexpr ChunkTag kTagGlsl{'G', 'L', 'S', 'L'};       // generated GLSL of one pass, for debugging
inline constexpr ChunkTag kTagEnvironment{'E', 'N', 'V', 'I'};  // the environment's lat-long image (1.1)

inline constexpr std::array<char, 4> kPackMagic{'F', 'G', 'P', 'K'};
inline constexpr std::uint16_t kPackVersionMajor = 1;  // a reader refuses a newer major version
inline constexpr std::uint16_t kPackVersionMinor = 1;  // newer minors only add chunk tags, skipped

inline std::string tag_text(const ChunkTag& t) { return std::string(t.data(), 4); }

}  // namespace fg
