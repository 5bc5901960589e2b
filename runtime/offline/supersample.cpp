#include "supersample.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace fg {

namespace {

double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double linear_to_srgb(double c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

const std::array<double, 256>& linear_table() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(i / 255.0);
        return t;
    }();
    return table;
}

}  // namespace

Rgba8Image downsample(const Rgba8Image& image, std::uint32_t factor) {
    if (factor <= 1) return image;
    const auto& lin = linear_table();
    Rgba8Image out{image.width / factor, image.height / factor, {}};
    out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    double n = static_cast<double>(factor) * factor;
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            double sum[4] = {0.0, 0.0, 0.0, 0.0};
            for (std::uint32_t sy = 0; sy < factor; ++sy)
                for (std::uint32_t sx = 0; sx < factor; ++sx) {
                    const std::uint8_t* p =
                        &image.pixels[((static_cast<std::size_t>(y) * factor + sy) * image.width + x * factor + sx) * 4];
                    for (int c = 0; c < 3; ++c) sum[c] += lin[p[c]];
                    sum[3] += p[3];
                }
            std::uint8_t* q = &out.pixels[(static_cast<std::size_t>(y) * out.width + x) * 4];
            for (int c = 0; c < 3; ++c)
                q[c] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(linear_to_srgb(sum[c] / n), 0.0, 1.0)));
            q[3] = static_cast<std::uint8_t>(std::lround(sum[3] / n));
        }
    return out;
}

Rgba8Image top_bottom(const Rgba8Image& top, const Rgba8Image& bottom) {
    Rgba8Image out{top.width, top.height + bottom.height, top.pixels};
    out.pixels.insert(out.pixels.end(), bottom.pixels.begin(), bottom.pixels.end());
    return out;
}

}  // namespace fg
