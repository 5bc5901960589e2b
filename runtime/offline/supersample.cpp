#include "supersample.h"

#include <cmath>

#include "linear_light.h"

namespace fg {

Rgba8Image downsample(const Rgba8Image& image, std::uint32_t factor) {
    if (factor <= 1) return image;
    const auto& lin = srgb8_linear_table();
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
            for (int c = 0; c < 3; ++c) q[c] = linear_to_srgb8(sum[c] / n);
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
