#include "display_transform.h"

namespace fg {

Rgba8Image display_picture(const std::vector<float>& hdr, std::uint32_t width, std::uint32_t height, std::uint32_t factor) {
    factor = std::max(factor, 1u);
    Rgba8Image out{width / factor, height / factor, {}};
    out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    const double n = static_cast<double>(factor) * factor;
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            double sum[4] = {0.0, 0.0, 0.0, 0.0};
            for (std::uint32_t sy = 0; sy < factor; ++sy)
                for (std::uint32_t sx = 0; sx < factor; ++sx)
                    for (int c = 0; c < 4; ++c)
                        sum[c] += hdr[((static_cast<std::size_t>(y) * factor + sy) * width + x * factor + sx) * 4 + c];
            std::uint8_t* q = &out.pixels[(static_cast<std::size_t>(y) * out.width + x) * 4];
            for (int c = 0; c < 3; ++c) q[c] = display_level(tonemap_beauty(sum[c] / n) * (sum[3] / n));
            q[3] = 255;
        }
    return out;
}

}  // namespace fg
