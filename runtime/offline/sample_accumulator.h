#pragma once
// Progressive accumulation: each sample is a whole frame rendered with its pixel grid moved by a
// sub-pixel offset (frame/sample_jitter.h); their mean in linear light is the picture of that many
// samples per pixel, at the output's size and detail, in the memory of one frame (supersampling
// renders factor^2 times the pixels at once). Deterministic: the same samples give the same bytes.
//
// Adaptive sampling adds a sample only to the tiles still sampling (SampledTiles), so each pixel
// keeps its own count; a pixel's noise is the standard error of its mean, estimated from the
// spread of its samples' display values (sRGB-encoded luma, 0 to 1: what the eye sees as grain).
#include <cstdint>
#include <vector>

#include "frame/dispatch_tiles.h"
#include "frame/image_output.h"

namespace fg {

class SampleAccumulator {
public:
    // Adds one sample, to the pixels of the tiles `sampled` keeps (all without); every sample has
    // the first one's size (std::invalid_argument otherwise). With `hdr` (the tone map's input,
    // RenderedFrame::hdr_left), the mean is of that, tone-mapped once; the picture still measures
    // the noise. Either every sample has one or none.
    void add(const Rgba8Image& sample, const SampledTiles* sampled = nullptr, const std::vector<float>* hdr = nullptr);
    std::uint32_t samples() const { return samples_; }
    // The mean so far, sRGB-encoded; an empty image before the first sample.
    Rgba8Image mean() const;
    // The mean tone map input, where the samples had one (else empty).
    std::vector<float> hdr_mean() const;
    // Samples each pixel took, row by row, and all of them together.
    const std::vector<std::uint32_t>& counts() const { return counts_; }
    std::uint64_t taken() const { return taken_; }
    // The standard error of pixel i's mean in display units (infinite below two samples).
    double noise(std::size_t pixel) const;
    // The tiles with a pixel whose noise is above `target`; `noisy_pixels` counts those pixels.
    SampledTiles tiles_above(double target, std::size_t* noisy_pixels = nullptr) const;

private:
    std::uint32_t width_ = 0, height_ = 0, samples_ = 0;
    std::vector<float> sum_;                 // linear RGB and alpha per pixel
    std::vector<double> hdr_sum_;            // the tone map's input and the fade's share, per pixel
    std::vector<std::uint32_t> counts_;      // samples per pixel
    std::uint64_t taken_ = 0;                // their sum
    std::vector<double> luma_, luma_squared_;   // sums of the display luma and its square
};

}  // namespace fg
