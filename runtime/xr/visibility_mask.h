#pragma once
// What the headset's optics show of each eye's image. OpenXR's XR_KHR_visibility_mask gives the
// hidden area as triangles on the z = -1 plane (tangents of the view angles); here they become
// one byte per pixel of the eye's render target, and then the frame graph's lens mask (an
// ellipse, frame/lens_mask.h) that encloses every visible pixel, so the mask never hides what the
// headset shows.
#include <cstdint>
#include <vector>

#include "frame/lens_mask.h"
#include "frame/stereo_rig.h"

namespace fg::xr {

struct VisibilityMask {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> visible;   // 1 = seen through the lens, rows top to bottom
    std::size_t triangles = 0;
    double hidden_fraction() const;
};

// `vertices` are (x, y) pairs on the z = -1 plane, y up; `indices` three per hidden triangle.
VisibilityMask rasterize_hidden_triangles(const std::vector<float>& vertices, const std::vector<std::uint32_t>& indices,
                                    const Fov& fov, std::uint32_t width, std::uint32_t height);

}  // namespace fg::xr

namespace fg::xr {

// The ellipse with `around`'s centre and proportions, just large enough to hold the centre of
// every visible pixel (plus half a pixel); no radii when nothing is hidden.
LensEllipse enclosing_lens(const VisibilityMask& mask, const LensEllipse& around);

}  // namespace fg::xr
