#include "frame_measures.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace fg::bench {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    double at = std::clamp(p / 100.0, 0.0, 1.0) * static_cast<double>(v.size() - 1);
    std::size_t below = static_cast<std::size_t>(std::floor(at));
    std::size_t above = std::min(below + 1, v.size() - 1);
    return v[below] + (v[above] - v[below]) * (at - static_cast<double>(below));
}

std::string shader_clock_paragraph(const std::vector<double>& mhz, unsigned max_mhz, const std::string& after) {
    if (mhz.empty()) return {};
    return fmt::format("Shader clock just after {} (NVML): median {:.0f} MHz, lowest {:.0f} MHz, of the GPU's {} "
                       "MHz.\n\n",
                       after, median(mhz), *std::min_element(mhz.begin(), mhz.end()), max_mhz);
}

double psnr(const Rgba8Image& a, const Rgba8Image& b, std::span<const std::uint8_t> visible) {
    double se = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        if (i % 4 == 3 || (i / 4 < visible.size() && !visible[i / 4])) continue;
        double d = static_cast<double>(a.pixels[i]) - b.pixels[i];
        se += d * d;
        ++n;
    }
    if (se == 0.0) return 99.0;
    return 10.0 * std::log10(255.0 * 255.0 / (se / static_cast<double>(n)));
}

double flicker(const Rgba8Image& now, const Rgba8Image& before, const Rgba8Image& truth_now,
               const Rgba8Image& truth_before, std::span<const std::uint8_t> visible) {
    double sum = 0.0;
    std::size_t n = 0;
    const std::size_t size = std::min({now.pixels.size(), before.pixels.size(), truth_now.pixels.size(), truth_before.pixels.size()});
    for (std::size_t i = 0; i < size; ++i) {
        if (i % 4 == 3 || (i / 4 < visible.size() && !visible[i / 4])) continue;
        const double change = static_cast<double>(now.pixels[i]) - before.pixels[i];
        const double truth_change = static_cast<double>(truth_now.pixels[i]) - truth_before.pixels[i];
        sum += std::abs(change - truth_change);
        ++n;
    }
    return n ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace fg::bench
