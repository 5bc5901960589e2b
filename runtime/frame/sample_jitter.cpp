#include "sample_jitter.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace fg {

namespace {

double radical_inverse(std::uint32_t i, std::uint32_t base) {
    double result = 0.0, digit = 1.0 / base;
    for (; i > 0; i /= base, digit /= base) result += (i % base) * digit;
    return result;
}

// Halton (2, 3) point k (from 1), centred on the pixel.
glm::dvec2 halton_offset(std::uint32_t k) { return {radical_inverse(k, 2) - 0.5, radical_inverse(k, 3) - 0.5}; }

}  // namespace

std::vector<glm::dvec2> lens_pattern(std::uint32_t n) {
    std::vector<glm::dvec2> out;
    for (std::uint32_t k = 1; k <= n; ++k) {
        const double a = 2.0 * radical_inverse(k, 5) - 1.0, b = 2.0 * radical_inverse(k, 7) - 1.0;
        if (a == 0.0 && b == 0.0) {
            out.push_back(glm::dvec2(0.0));
            continue;
        }
        const double quarter = 0.25 * glm::pi<double>();
        const double r = std::abs(a) > std::abs(b) ? a : b;
        const double phi = std::abs(a) > std::abs(b) ? quarter * (b / a) : 2.0 * quarter - quarter * (a / b);
        out.push_back(r * glm::dvec2(std::cos(phi), std::sin(phi)));
    }
    return out;
}

std::vector<double> shutter_pattern(std::uint32_t n) {
    std::vector<double> out;
    for (std::uint32_t k = 0; k < n; ++k) out.push_back(radical_inverse(k, 11));
    return out;
}

std::uint32_t taa_phases(double upscale) {
    const auto side = static_cast<std::uint32_t>(std::lround(4.0 * std::max(1.0, upscale)));
    return side * side;
}

glm::dvec2 taa_jitter(std::uint64_t history_frames, double upscale) {
    static const std::vector<glm::dvec2> native = sample_pattern(taa_phases(1.0));
    if (upscale <= 1.0) return native[history_frames % native.size()];
    const std::vector<glm::dvec2> pattern = sample_pattern(taa_phases(upscale));
    return pattern[history_frames % pattern.size()];
}

std::vector<glm::dvec2> sample_pattern(std::uint32_t n) {
    if (n <= 1) return {glm::dvec2(0.0)};
    std::vector<glm::dvec2> out;
    const auto s = static_cast<std::uint32_t>(std::lround(std::sqrt(static_cast<double>(n))));
    if (s * s != n) {
        // Index 0 is (0, 0), a pixel's corner: start at 1, so the first sample sits inside.
        for (std::uint32_t k = 1; k <= n; ++k) out.push_back(halton_offset(k));
        return out;
    }
    std::vector<bool> taken(n, false);
    // Halton points are dense: every cell is visited; the bound only guards the loop.
    for (std::uint32_t k = 1; out.size() < n && k < 1000u * n; ++k) {
        glm::dvec2 h = halton_offset(k) + 0.5;
        auto x = static_cast<std::uint32_t>(h.x * s), y = static_cast<std::uint32_t>(h.y * s);
        if (taken[y * s + x]) continue;
        taken[y * s + x] = true;
        out.push_back({(x + 0.5) / s - 0.5, (y + 0.5) / s - 0.5});
    }
    for (std::uint32_t c = 0; out.size() < n; ++c)
        if (!taken[c]) out.push_back({(c % s + 0.5) / s - 0.5, (c / s + 0.5) / s - 0.5});
    return out;
}

}  // namespace fg
