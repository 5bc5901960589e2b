#include "sample_accumulator.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "display_transform.h"
#include "linear_light.h"

namespace fg {

void SampleAccumulator::add(const Rgba8Image& sample, const SampledTiles* sampled, const std::vector<float>* hdr) {
    if (samples_ == 0) {
        if (hdr) hdr_sum_.assign(static_cast<std::size_t>(sample.width) * sample.height * 4, 0.0);
        width_ = sample.width;
        height_ = sample.height;
        const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
        sum_.assign(pixels * 4, 0.0f);
        counts_.assign(pixels, 0);
        luma_.assign(pixels, 0.0);
        luma_squared_.assign(pixels, 0.0);
    } else if (sample.width != width_ || sample.height != height_) {
        throw std::invalid_argument("a sample's size differs from the first sample's");
    }
    if ((hdr != nullptr) != !hdr_sum_.empty() || (hdr && hdr->size() != hdr_sum_.size()))
        throw std::invalid_argument("a sample's tone map input differs from the first sample's");
    const auto& lin = srgb8_linear_table();
    for (std::uint32_t y = 0; y < height_; ++y)
        for (std::uint32_t x = 0; x < width_; ++x) {
            if (sampled && !sampled->takes(x / 8, y / 8)) continue;
            const std::size_t p = static_cast<std::size_t>(y) * width_ + x;
            const std::uint8_t* c = &sample.pixels[4 * p];
            for (int k = 0; k < 3; ++k) sum_[4 * p + k] += static_cast<float>(lin[c[k]]);
            if (hdr)
                for (int k = 0; k < 4; ++k) hdr_sum_[4 * p + k] += (*hdr)[4 * p + k];
            sum_[4 * p + 3] += c[3];
            // Rec. 709 weights on the encoded values: a display luma.
            const double luma = (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]) / 255.0;
            luma_[p] += luma;
            luma_squared_[p] += luma * luma;
            ++counts_[p];
            ++taken_;
        }
    ++samples_;
}

Rgba8Image SampleAccumulator::mean() const {
    if (!hdr_sum_.empty()) return display_picture(hdr_mean(), width_, height_);
    Rgba8Image out{width_, height_, std::vector<std::uint8_t>(sum_.size())};
    for (std::size_t i = 0; i < sum_.size(); ++i) {
        const double n = std::max<std::uint32_t>(counts_[i / 4], 1);
        out.pixels[i] = i % 4 == 3 ? static_cast<std::uint8_t>(std::lround(sum_[i] / n)) : linear_to_srgb8(sum_[i] / n);
    }
    return out;
}

std::vector<float> SampleAccumulator::hdr_mean() const {
    std::vector<float> out(hdr_sum_.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<float>(hdr_sum_[i] / std::max<std::uint32_t>(counts_[i / 4], 1));
    return out;
}

double SampleAccumulator::noise(std::size_t pixel) const {
    const double n = counts_[pixel];
    if (n < 2.0) return std::numeric_limits<double>::infinity();
    const double mean = luma_[pixel] / n;
    const double variance = std::max(luma_squared_[pixel] / n - mean * mean, 0.0) * n / (n - 1.0);
    return std::sqrt(variance / n);
}

SampledTiles SampleAccumulator::tiles_above(double target, std::size_t* noisy_pixels) const {
    SampledTiles noisy(width_, height_);
    std::fill(noisy.active.begin(), noisy.active.end(), 0);
    std::size_t above = 0;
    for (std::uint32_t y = 0; y < height_; ++y)
        for (std::uint32_t x = 0; x < width_; ++x)
            if (noise(static_cast<std::size_t>(y) * width_ + x) > target) {
                noisy.active[std::size_t(y / 8) * noisy.columns + x / 8] = 1;
                ++above;
            }
    if (noisy_pixels) *noisy_pixels = above;
    return noisy;
}

}  // namespace fg
