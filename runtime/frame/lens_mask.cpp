#include "lens_mask.h"

#include <algorithm>
#include <cmath>

namespace fg {

LensEllipse lens_ellipse(const View& view) {
    LensEllipse e;
    e.centre_u = -view.fov.left / (view.fov.right - view.fov.left);
    e.centre_v = view.fov.up / (view.fov.up - view.fov.down);
    e.radius_u = std::max(e.centre_u, 1.0 - e.centre_u);
    e.radius_v = std::max(e.centre_v, 1.0 - e.centre_v);
    return e;
}

std::vector<std::uint8_t> visible_pixels(const LensEllipse& lens, std::uint32_t width, std::uint32_t height) {
    std::vector<std::uint8_t> visible(static_cast<std::size_t>(width) * height, 1);
    if (lens.radius_u <= 0.0) return visible;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            // Single precision in the shader's order, so both agree on the boundary pixels.
            float qu = ((static_cast<float>(x) + 0.5f) / static_cast<float>(width) - static_cast<float>(lens.centre_u)) /
                       static_cast<float>(lens.radius_u);
            float qv = ((static_cast<float>(y) + 0.5f) / static_cast<float>(height) - static_cast<float>(lens.centre_v)) /
                       static_cast<float>(lens.radius_v);
            visible[static_cast<std::size_t>(y) * width + x] = qu * qu + qv * qv > 1.0f ? 0 : 1;
        }
    return visible;
}

std::vector<std::uint8_t> marched_pixels(const GpuFrame& frame, int view) {
    const std::uint32_t width = frame.eye_size.x, height = frame.eye_size.y;
    std::vector<std::uint8_t> marched(static_cast<std::size_t>(width) * height, 1);
    if (frame.fovea_radius <= 0.0f) return marched;
    // fg_fovea_centre and fg_periphery (common.glsl), in single precision and the shader's order.
    const GpuView& v = frame.views[view];
    const float cx = (v.lens_radii.x > 0.0f ? v.lens_centre.x : 0.5f) * static_cast<float>(width);
    const float cy = (v.lens_radii.x > 0.0f ? v.lens_centre.y : 0.5f) * static_cast<float>(height);
    const float half = 0.5f * static_cast<float>(height), blend = std::max(frame.fovea_blend, 1e-6f);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            if (((x | y) & 1u) == 0) continue;
            float dx = static_cast<float>(x) + 0.5f - cx, dy = static_cast<float>(y) + 0.5f - cy;
            float r = std::sqrt(dx * dx + dy * dy) / half;
            if (std::clamp((r - frame.fovea_radius) / blend, 0.0f, 1.0f) >= 1.0f)
                marched[static_cast<std::size_t>(y) * width + x] = 0;
        }
    return marched;
}

}  // namespace fg
