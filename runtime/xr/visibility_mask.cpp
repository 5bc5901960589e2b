#include "xr/visibility_mask.h"

#include <algorithm>
#include <cmath>

namespace fg::xr {

double VisibilityMask::hidden_fraction() const {
    if (visible.empty()) return 0.0;
    auto hidden = std::count(visible.begin(), visible.end(), std::uint8_t{0});
    return static_cast<double>(hidden) / static_cast<double>(visible.size());
}

VisibilityMask rasterize_hidden_triangles(const std::vector<float>& vertices, const std::vector<std::uint32_t>& indices,
                                    const Fov& fov, std::uint32_t width, std::uint32_t height) {
    VisibilityMask mask;
    mask.width = width;
    mask.height = height;
    mask.visible.assign(static_cast<std::size_t>(width) * height, 1);
    const std::size_t vertex_count = vertices.size() / 2;
    auto edge = [](double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    };
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        if (i0 >= vertex_count || i1 >= vertex_count || i2 >= vertex_count) continue;   // a bad index hides nothing
        ++mask.triangles;
        double x0 = vertices[2 * i0], y0 = vertices[2 * i0 + 1];
        double x1 = vertices[2 * i1], y1 = vertices[2 * i1 + 1];
        double x2 = vertices[2 * i2], y2 = vertices[2 * i2 + 1];
        double area = edge(x0, y0, x1, y1, x2, y2);
        if (std::abs(area) < 1e-12) continue;
        for (std::uint32_t y = 0; y < height; ++y) {
            // Pixel centres on the tangent plane; image rows run downwards, tangents upwards.
            double ty = fov.up + (fov.down - fov.up) * ((y + 0.5) / height);
            for (std::uint32_t x = 0; x < width; ++x) {
                double tx = fov.left + (fov.right - fov.left) * ((x + 0.5) / width);
                double w0 = edge(x1, y1, x2, y2, tx, ty), w1 = edge(x2, y2, x0, y0, tx, ty), w2 = edge(x0, y0, x1, y1, tx, ty);
                bool inside = area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
                if (inside) mask.visible[static_cast<std::size_t>(y) * width + x] = 0;
            }
        }
    }
    return mask;
}

}  // namespace fg::xr

namespace fg::xr {

LensEllipse enclosing_lens(const VisibilityMask& mask, const LensEllipse& around) {
    if (mask.visible.empty() || around.radius_u <= 0.0 || mask.hidden_fraction() == 0.0) return {};
    double scale = 0.0;
    for (std::uint32_t y = 0; y < mask.height; ++y)
        for (std::uint32_t x = 0; x < mask.width; ++x) {
            if (!mask.visible[static_cast<std::size_t>(y) * mask.width + x]) continue;
            double qu = ((x + 0.5) / mask.width - around.centre_u) / around.radius_u;
            double qv = ((y + 0.5) / mask.height - around.centre_v) / around.radius_v;
            scale = std::max(scale, std::sqrt(qu * qu + qv * qv));
        }
    LensEllipse out = around;
    out.radius_u = around.radius_u * scale + 0.5 / mask.width;
    out.radius_v = around.radius_v * scale + 0.5 / mask.height;
    return out;
}

}  // namespace fg::xr
