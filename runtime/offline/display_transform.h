#pragma once
// The shade pass's display transform on the CPU (post_effects.glsl: fg_tonemap, then the 8-bit
// store), for colours averaged before it: accumulated samples and supersampled pixels
// (FrameSettings::hdr), and the HDR beauty of a 16-bit PNG.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "frame/image_output.h"

namespace fg {

// Narkowicz's ACES fit of one channel already scaled by the exposure: a display value in [0, 1].
inline double tonemap_beauty(double c) {
    return std::clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

// The 8-bit level a display value is stored as (a UNORM image: rounded to the nearest).
inline std::uint8_t display_level(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// The picture of a `width` x `height` image of tone map inputs (RenderedFrame::hdr_left: rgb, and
// alpha the share the fade keeps), each `factor` x `factor` block averaged into one output pixel
// before the tone map.
Rgba8Image display_picture(const std::vector<float>& hdr, std::uint32_t width, std::uint32_t height, std::uint32_t factor = 1);

}  // namespace fg
