#pragma once
// The lens mask ("iris"): which pixels of an eye's image the headset's optics show. OpenXR's
// XR_KHR_visibility_mask gives the hidden area as triangles on the z = -1 plane (tangents of the
// view angles); here they become one byte per pixel of the eye's render target.
#include <cstdint>
#include <vector>

#include "frame/stereo_rig.h"

namespace fg::xr {

struct LensMask {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> visible;   // 1 = seen through the lens, rows top to bottom
    std::size_t triangles = 0;
    double hidden_fraction() const;
};

// `vertices` are (x, y) pairs on the z = -1 plane, y up; `indices` three per hidden triangle.
LensMask rasterize_hidden_triangles(const std::vector<float>& vertices, const std::vector<std::uint32_t>& indices,
                                    const Fov& fov, std::uint32_t width, std::uint32_t height);

}  // namespace fg::xr
