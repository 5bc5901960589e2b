#pragma once
// 8-bit sRGB codes to linear light and back (IEC 61966-2-1): pictures are averaged in linear light,
// so edges against a bright background do not darken.
#include <array>
#include <cstdint>

namespace fg {

// Linear light of each 8-bit sRGB code.
const std::array<double, 256>& srgb8_linear_table();
// The nearest 8-bit sRGB code of a linear value (clamped to [0, 1]).
std::uint8_t linear_to_srgb8(double linear);

}  // namespace fg
