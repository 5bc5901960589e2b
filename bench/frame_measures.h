#pragma once
// What both benchmarks measure frames with: robust statistics of per-frame figures, and how far an
// image is from a reference (PSNR) and how much more it flickers than its ground truth.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frame/image_output.h"

namespace fg::bench {

double median(std::vector<double> v);
// Linear interpolation between the closest ranks (numpy's default); 0 for no values.
double percentile(std::vector<double> v, double p);

// What a report says of an NVIDIA GPU's shader clock read after timed frames (`after`, such as "each
// timed frame"): its median and lowest of the GPU's `max_mhz`, as a paragraph; empty without readings.
std::string shader_clock_paragraph(const std::vector<double>& mhz, unsigned max_mhz, const std::string& after);

// Over the visible pixels only, when `visible` (lens_mask.h) is given; 99 dB for equal images.
double psnr(const Rgba8Image& a, const Rgba8Image& b, std::span<const std::uint8_t> visible);

// Flicker: how a frame changed from the one before that its ground truth did not, the mean over
// visible pixels and channels of |(now - before) - (truth_now - truth_before)|, in 8-bit levels.
// Shimmer of sub-pixel detail counts; a change the truth shows too (motion) does not.
double flicker(const Rgba8Image& now, const Rgba8Image& before, const Rgba8Image& truth_now,
               const Rgba8Image& truth_before, std::span<const std::uint8_t> visible);

}  // namespace fg::bench
