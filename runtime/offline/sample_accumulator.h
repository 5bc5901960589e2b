#pragma once
// Progressive accumulation: each sample is a whole frame rendered with its pixel grid moved by a
// sub-pixel offset (frame/sample_jitter.h); their mean in linear light is the picture of that many
// samples per pixel, at the output's size and detail, in the memory of one frame (supersampling
// renders factor^2 times the pixels at once). Deterministic: the same samples give the same bytes.
#include <cstdint>
#include <vector>

#include "frame/image_output.h"

namespace fg {

class SampleAccumulator {
public:
    // Adds one sample; every sample has the first one's size (std::invalid_argument otherwise).
    void add(const Rgba8Image& sample);
    std::uint32_t samples() const { return samples_; }
    // The mean so far, sRGB-encoded; an empty image before the first sample.
    Rgba8Image mean() const;

private:
    std::uint32_t width_ = 0, height_ = 0, samples_ = 0;
    std::vector<float> sum_;   // linear RGB and alpha per pixel
};

}  // namespace fg
