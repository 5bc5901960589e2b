#pragma once
// The shade pass's display transform on the CPU (post_effects.glsl: fg_tonemap, then the 8-bit
// store), for samples averaged before it (FrameSettings::hdr).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fg {

// Narkowicz's ACES fit of a colour channel already scaled by the exposure, clamped to [0, 1].
inline double tone_map(double c) {
    c = std::max(c, 0.0);
    return std::clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

// The 8-bit level a [0, 1] display value is stored as (a UNORM image: rounded to the nearest).
inline std::uint8_t display_level(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

}  // namespace fg
