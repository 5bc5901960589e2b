#pragma once
// The lens mask (seed 001's "iris") and fixed foveation, as the shaders decide them
// (shaders/common.glsl: fg_outside_lens, fg_periphery, fg_foveated_away), mirrored on the CPU so
// the benchmark and the tests judge only the pixels a viewer can see.
#include <cstdint>
#include <vector>

#include "gpu_uniforms.h"
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

// 1 where eye `view` of `frame` marches a pixel itself, 0 where fixed foveation's fill copies the
// depth of its 2x2 block's even pixel (the odd pixels of the periphery: fovea.comp). Every pixel
// without foveation. Lets the benchmark tell the march's errors from the fill's.
std::vector<std::uint8_t> marched_pixels(const GpuFrame& frame, int view);

}  // namespace fg
