#include "sample_accumulator.h"

#include <cmath>
#include <stdexcept>

#include "linear_light.h"

namespace fg {

void SampleAccumulator::add(const Rgba8Image& sample) {
    if (samples_ == 0) {
        width_ = sample.width;
        height_ = sample.height;
        sum_.assign(static_cast<std::size_t>(width_) * height_ * 4, 0.0f);
    } else if (sample.width != width_ || sample.height != height_) {
        throw std::invalid_argument("a sample's size differs from the first sample's");
    }
    const auto& lin = srgb8_linear_table();
    for (std::size_t i = 0; i < sum_.size(); ++i)
        sum_[i] += i % 4 == 3 ? sample.pixels[i] : static_cast<float>(lin[sample.pixels[i]]);
    ++samples_;
}

Rgba8Image SampleAccumulator::mean() const {
    Rgba8Image out{width_, height_, std::vector<std::uint8_t>(sum_.size())};
    const double n = samples_;
    for (std::size_t i = 0; i < sum_.size(); ++i)
        out.pixels[i] = i % 4 == 3 ? static_cast<std::uint8_t>(std::lround(sum_[i] / n)) : linear_to_srgb8(sum_[i] / n);
    return out;
}

}  // namespace fg
