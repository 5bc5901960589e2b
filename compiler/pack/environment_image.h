#pragma once
// The environment's lat-long image as a pack carries it (chunk ENVI): half-float RGBA texels, row 0
// straight up (+y), the middle column looking down -z, turning right (towards +x) to the right, as
// fgplay's own equirectangular panoramas are laid out.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fg {

struct EnvironmentImage {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint16_t> rgba;   // IEEE half bits, 4 per texel, row by row from the top
    bool operator==(const EnvironmentImage&) const = default;
};

// The chunk payload: width and height (u32, little-endian), then the texels.
std::vector<std::uint8_t> environment_payload(const EnvironmentImage& image);
// Nullopt and `error` set when the payload's size disagrees with its header.
std::optional<EnvironmentImage> environment_from_payload(std::span<const std::uint8_t> payload, std::string& error);

}  // namespace fg
