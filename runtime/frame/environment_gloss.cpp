#include "environment_gloss.h"
#include "lat_long.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include <Imath/half.h>

namespace fg {

namespace {

constexpr double kPi = std::numbers::pi;

// A lat-long image in float, each texel with its direction and solid angle.
struct Sphere {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb;         // 3 per texel
    std::vector<float> direction;   // 3 per texel, unit, in the image's frame
    std::vector<float> solid_angle; // per row
};

Sphere sphere_of_size(std::uint32_t w, std::uint32_t h) {
    Sphere s;
    s.width = w;
    s.height = h;
    s.rgb.assign(std::size_t(w) * h * 3, 0.0f);
    s.direction.resize(std::size_t(w) * h * 3);
    s.solid_angle.resize(h);
    for (std::uint32_t j = 0; j < h; ++j) {
        s.solid_angle[j] = static_cast<float>(lat_long_solid_angle(j, w, h));
        for (std::uint32_t i = 0; i < w; ++i) {
            const glm::dvec3 d = lat_long_direction(i, j, w, h);
            for (int k = 0; k < 3; ++k) s.direction[3 * (std::size_t(j) * w + i) + k] = static_cast<float>(d[k]);
        }
    }
    return s;
}

// A lat-long image of from_w x from_h texels (`texel(t, c)`: channel c of texel t) at no more than
// `width` columns: each texel of the smaller one is the mean, by solid angle, of the texels whose
// centres fall in it.
template <class Texel>
Sphere resampled(std::uint32_t from_w, std::uint32_t from_h, Texel texel, std::uint32_t width) {
    const std::uint32_t w = std::min(width, from_w), h = std::max(1u, from_h * w / from_w);
    Sphere s = sphere_of_size(w, h);
    std::vector<double> sum(std::size_t(w) * h * 3, 0.0), weight(std::size_t(w) * h, 0.0);
    for (std::uint32_t j = 0; j < from_h; ++j) {
        const double omega = lat_long_solid_angle(j, from_w, from_h);
        const std::uint32_t to_j = std::min(h - 1, static_cast<std::uint32_t>((j + 0.5) * h / from_h));
        for (std::uint32_t i = 0; i < from_w; ++i) {
            const std::uint32_t to_i = std::min(w - 1, static_cast<std::uint32_t>((i + 0.5) * w / from_w));
            const std::size_t from = std::size_t(j) * from_w + i, to = std::size_t(to_j) * w + to_i;
            for (int c = 0; c < 3; ++c) sum[3 * to + c] += omega * texel(from, c);
            weight[to] += omega;
        }
    }
    for (std::size_t t = 0; t < weight.size(); ++t)
        for (int c = 0; c < 3; ++c) s.rgb[3 * t + c] = weight[t] > 0.0 ? static_cast<float>(sum[3 * t + c] / weight[t]) : 0.0f;
    return s;
}

Sphere resampled(const EnvironmentImage& image, std::uint32_t width) {
    return resampled(image.width, image.height, [&](std::size_t t, int c) { return half_value(image.rgba[4 * t + c]); }, width);
}

Sphere resampled(const Sphere& sphere, std::uint32_t width) {
    return resampled(sphere.width, sphere.height, [&](std::size_t t, int c) { return double(sphere.rgb[3 * t + c]); }, width);
}

// The source convolved with the lobe of GGX alpha `alpha` about each texel's direction, the view
// along it (n = v = r): each direction l weighted by D(h) (n . l), h halving r and l. The lobe is
// cut where the directions beyond hold 1 % of it (tan of the half angle at 10 alpha).
Sphere convolved(const Sphere& source, std::uint32_t w, std::uint32_t h, double alpha) {
    Sphere out = sphere_of_size(w, h);
    const double a2 = alpha * alpha;
    const double reach = std::min(kPi / 2.0, 2.0 * std::atan(10.0 * alpha));
    const float cut = static_cast<float>(std::cos(reach));
    for (std::uint32_t j = 0; j < h; ++j) {
        const double theta = (j + 0.5) * kPi / h;
        const auto first = static_cast<std::uint32_t>(std::clamp((theta - reach) / kPi * source.height - 1.0, 0.0, double(source.height)));
        const auto last = static_cast<std::uint32_t>(std::clamp((theta + reach) / kPi * source.height + 1.0, 0.0, double(source.height)));
        // The columns of each row within `reach` of the row's directions, either side of their own
        // column: cos(reach) = cos(theta) cos(theta_s) + sin(theta) sin(theta_s) cos(phi - phi_r),
        // and a column either side to spare.
        std::vector<std::int64_t> span(source.height, 0);
        for (std::uint32_t sj = first; sj < last; ++sj) {
            const double row_theta = (sj + 0.5) * kPi / source.height;
            const double across = (std::cos(reach) - std::cos(theta) * std::cos(row_theta)) /
                                  std::max(std::sin(theta) * std::sin(row_theta), 1e-12);
            const double half = across <= -1.0 ? kPi : std::acos(std::min(across, 1.0));
            span[sj] = static_cast<std::int64_t>(std::ceil(half / (2.0 * kPi) * source.width)) + 1;
        }
        for (std::uint32_t i = 0; i < w; ++i) {
            const float* r = &out.direction[3 * (std::size_t(j) * w + i)];
            const double centre = (i + 0.5) / w * source.width - 0.5;   // r's column in the source
            double sum[3] = {0.0, 0.0, 0.0}, total = 0.0;
            for (std::uint32_t sj = first; sj < last; ++sj) {
                const auto from = static_cast<std::int64_t>(std::floor(centre)) - span[sj];
                const std::int64_t count = std::min<std::int64_t>(2 * span[sj] + 2, source.width);
                auto si = static_cast<std::uint32_t>((from % source.width + source.width) % source.width);
                for (std::int64_t k = 0; k < count; ++k, si = si + 1 == source.width ? 0 : si + 1) {
                    const std::size_t t = std::size_t(sj) * source.width + si;
                    const float* l = &source.direction[3 * t];
                    const float c = r[0] * l[0] + r[1] * l[1] + r[2] * l[2];
                    if (c <= cut) continue;
                    // (n . h)^2 = (1 + r . l) / 2; D up to its constant.
                    const double q = 0.5 * (1.0 + c) * (a2 - 1.0) + 1.0;
                    const double weight = c * source.solid_angle[sj] / (q * q);
                    for (int c3 = 0; c3 < 3; ++c3) sum[c3] += weight * source.rgb[3 * t + c3];
                    total += weight;
                }
            }
            for (int k = 0; k < 3; ++k)
                out.rgb[3 * (std::size_t(j) * w + i) + k] = total > 0.0 ? static_cast<float>(sum[k] / total) : 0.0f;
        }
    }
    return out;
}

constexpr int kSharePoints = 1024;

// What the lobe of roughness r reflects of white light from everywhere, seen at cos_view from the
// normal: F0 * A + B. The halfway vectors are drawn by D (n . h) on a Hammersley set, so each
// direction counts 4 Vis (n . l) (v . h) / (n . h).
std::pair<double, double> reflected_share(double cos_view, double roughness) {
    const double alpha = roughness * roughness, a2 = alpha * alpha;
    const double vx = std::sqrt(1.0 - cos_view * cos_view), vz = cos_view;
    // cos(2 pi u2), u2 the point's bits mirrored about the point (van der Corput).
    static const std::vector<double> turn = [] {
        std::vector<double> c(kSharePoints);
        for (int k = 0; k < kSharePoints; ++k) {
            double u2 = 0.0;
            for (int bits = k, scale = 2; bits != 0; bits >>= 1, scale *= 2) u2 += double(bits & 1) / scale;
            c[k] = std::cos(2.0 * kPi * u2);
        }
        return c;
    }();
    double a = 0.0, b = 0.0;
    for (int k = 0; k < kSharePoints; ++k) {
        const double u1 = (k + 0.5) / kSharePoints;
        const double cos_h = std::sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1)), sin_h = std::sqrt(1.0 - cos_h * cos_h);
        const double hx = sin_h * turn[k], hz = cos_h;
        const double vh = vx * hx + vz * hz;
        const double lz = 2.0 * vh * hz - vz;
        if (lz <= 0.0 || vh <= 0.0) continue;
        const double visibility = 0.5 / (lz * std::sqrt(vz * vz * (1.0 - a2) + a2) + vz * std::sqrt(lz * lz * (1.0 - a2) + a2));
        const double grazing = 1.0 - vh, edge = grazing * grazing * grazing * grazing * grazing;
        const double share = 4.0 * visibility * lz * vh / hz;
        a += share * (1.0 - edge);
        b += share * edge;
    }
    return {a / kSharePoints, b / kSharePoints};
}

}  // namespace

void append_environment_gloss(const EnvironmentImage& image, std::vector<std::uint32_t>& words) {
    auto put = [&](double v) { words.push_back(std::bit_cast<std::uint32_t>(static_cast<float>(v))); };
    words[2] = static_cast<std::uint32_t>(words.size());
    for (std::uint32_t j = 0; j < kGlossTableSize; ++j)
        for (std::uint32_t i = 0; i < kGlossTableSize; ++i) {
            const auto [a, b] = reflected_share((i + 0.5) / kGlossTableSize, (j + 0.5) / kGlossTableSize);
            put(a);
            put(b);
        }
    // The sharper levels need finer texels: none wider than its lobe. The image is read once.
    const Sphere fine = resampled(image, 128), middle = resampled(fine, 64), coarse = resampled(middle, 32);
    const Sphere* sources[kGlossLevels] = {&fine, &middle, &coarse, &coarse, &coarse};
    const std::uint32_t widths[kGlossLevels] = {128, 64, 32, 32, 32};
    std::vector<Sphere> levels;
    for (std::uint32_t k = 0; k < kGlossLevels; ++k) {
        const double roughness = 0.2 * (k + 1);
        levels.push_back(convolved(*sources[k], widths[k], widths[k] / 2, roughness * roughness));
    }
    std::size_t at = words.size() + 4 * kGlossLevels;
    for (const Sphere& level : levels) {
        words.insert(words.end(), {level.width, level.height, static_cast<std::uint32_t>(at), 0u});
        at += std::size_t(level.width) * level.height * 2;
    }
    for (const Sphere& level : levels)
        for (std::size_t t = 0; t < std::size_t(level.width) * level.height; ++t) {
            const auto half = [&](int c) { return std::uint32_t(Imath::half(level.rgb[3 * t + c]).bits()); };
            words.push_back(half(0) | (half(1) << 16));
            words.push_back(half(2) | (std::uint32_t(Imath::half(1.0f).bits()) << 16));
        }
}

}  // namespace fg
