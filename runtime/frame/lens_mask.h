#pragma once
// The lens mask (seed 001's "iris") and fixed foveation, as the shaders decide them
// (shaders/common.glsl: fg_outside_lens, fg_periphery, fg_foveated_away), mirrored on the CPU so
// the benchmark and the tests judge only the pixels a viewer can see.
#include <cstdint>
#include <vector>

#include "stereo_rig.h"

namespace fg {

// An ellipse in the view's uv space: centre where the optical axis meets the image, reaching the
// image's farther edges (for a symmetric view: the inscribed ellipse, 21.5 % of pixels hidden).
struct LensEllipse {
    double centre_u = 0.5, centre_v = 0.5, radius_u = 0.0, radius_v = 0.0;   // radii 0: no mask
};

LensEllipse lens_ellipse(const View& view);

// 1 where a pixel is visible through the lens (every pixel when `lens` has no radii).
std::vector<std::uint8_t> visible_pixels(const LensEllipse& lens, std::uint32_t width, std::uint32_t height);

}  // namespace fg
