#include "environment_light.h"

#include <array>
#include <bit>
#include <cmath>
#include <numbers>

#include <Imath/half.h>

#include "environment_gloss.h"
#include "lat_long.h"

namespace fg {

namespace {

// The nine real spherical harmonics at unit direction d (x, y, z).
std::array<double, 9> harmonics(double x, double y, double z) {
    return {0.282095,          0.488603 * y,     0.488603 * z,
            0.488603 * x,      1.092548 * x * y, 1.092548 * y * z,
            0.315392 * (3.0 * z * z - 1.0), 1.092548 * x * z, 0.546274 * (x * x - y * y)};
}

}  // namespace

std::vector<std::uint32_t> environment_words(const EnvironmentImage& image) {
    const std::uint32_t w = image.width, h = image.height;
    const double pi = std::numbers::pi;
    std::vector<std::uint32_t> words(kEnvironmentTablesAt + (h + 1) + std::size_t(h) * (w + 1) + std::size_t(w) * h * 2, 0);
    words[0] = w;
    words[1] = h;
    auto put = [&](std::size_t at, double v) { words[at] = std::bit_cast<std::uint32_t>(static_cast<float>(v)); };

    // Project the radiance onto the harmonics texel by texel (each texel's exact solid angle), then
    // convolve with the clamped cosine: 1, 2/3 and 1/4 of pi for orders 0, 1, 2, over pi.
    std::array<std::array<double, 3>, 9> sh{};
    std::vector<double> row_sum(h, 0.0), weight(std::size_t(w) * h);
    for (std::uint32_t j = 0; j < h; ++j) {
        const double theta = (j + 0.5) * pi / h, solid_angle = lat_long_solid_angle(j, w, h);
        for (std::uint32_t i = 0; i < w; ++i) {
            const std::size_t t = std::size_t(j) * w + i;
            const double r = half_value(image.rgba[4 * t]), g = half_value(image.rgba[4 * t + 1]),
                         b = half_value(image.rgba[4 * t + 2]);
            const glm::dvec3 d = lat_long_direction(i, j, w, h);
            const auto y = harmonics(d.x, d.y, d.z);
            for (int k = 0; k < 9; ++k) {
                sh[k][0] += r * y[k] * solid_angle;
                sh[k][1] += g * y[k] * solid_angle;
                sh[k][2] += b * y[k] * solid_angle;
            }
            weight[t] = (0.2126 * r + 0.7152 * g + 0.0722 * b) * std::sin(theta);
            row_sum[j] += weight[t];
        }
    }
    const std::array<double, 9> lobe = {1.0, 2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25, 0.25, 0.25, 0.25, 0.25};
    for (int k = 0; k < 9; ++k)
        for (int c = 0; c < 3; ++c) put(kEnvironmentHarmonicsAt + 4 * k + c, lobe[k] * sh[k][c]);

    // The tables: a black image draws by solid angle alone.
    double total = 0.0;
    for (double s : row_sum) total += s;
    if (total <= 0.0) {
        total = 0.0;
        for (std::uint32_t j = 0; j < h; ++j) {
            row_sum[j] = 0.0;
            for (std::uint32_t i = 0; i < w; ++i) row_sum[j] += weight[std::size_t(j) * w + i] = std::sin((j + 0.5) * pi / h);
            total += row_sum[j];
        }
    }
    std::size_t at = kEnvironmentTablesAt;
    double running = 0.0;
    put(at++, 0.0);
    for (std::uint32_t j = 0; j < h; ++j) {
        running += row_sum[j];
        put(at++, j + 1 == h ? 1.0 : running / total);
    }
    for (std::uint32_t j = 0; j < h; ++j) {
        double row = 0.0;
        put(at++, 0.0);
        for (std::uint32_t i = 0; i < w; ++i) {
            row += weight[std::size_t(j) * w + i];
            // A black row is never drawn; its columns still form a valid table.
            put(at++, i + 1 == w ? 1.0 : row_sum[j] > 0.0 ? row / row_sum[j] : (i + 1.0) / w);
        }
    }
    for (std::size_t t = 0; t < std::size_t(w) * h; ++t) {
        words[at++] = image.rgba[4 * t] | (std::uint32_t(image.rgba[4 * t + 1]) << 16);
        words[at++] = image.rgba[4 * t + 2] | (std::uint32_t(image.rgba[4 * t + 3]) << 16);
    }
    append_environment_gloss(image, words);
    return words;
}

EnvironmentImage uniform_environment() {
    EnvironmentImage image;
    image.width = 64;
    image.height = 32;
    image.rgba.assign(std::size_t(64) * 32 * 4, Imath::half(1.0f).bits());
    return image;
}

}  // namespace fg
