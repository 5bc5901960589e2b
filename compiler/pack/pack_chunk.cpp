#include "pack_chunk.h"

#include <cstring>

namespace fg {

std::vector<std::uint8_t> ManifestChunk::payload() const {
    std::string text = manifest_.dump(2);
    return {text.begin(), text.end()};
}

std::vector<std::uint8_t> SpirvChunk::payload() const {
    std::vector<std::uint8_t> bytes(words_.size() * 4);
    // SPIR-V words are stored little-endian, as the format says; this machine is little-endian.
    std::memcpy(bytes.data(), words_.data(), bytes.size());
    return bytes;
}

std::vector<std::uint8_t> TextChunk::payload() const { return {text_.begin(), text_.end()}; }

}  // namespace fg
