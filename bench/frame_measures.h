#pragma once
// What both benchmarks measure frames with: robust statistics of per-frame figures, and the PSNR of
// an image against the strict reference (frame/strict_reference.h).
#include <cstdint>
#include <span>
#include <vector>

#include "frame/image_output.h"

namespace fg::bench {

double median(std::vector<double> v);
// Linear interpolation between the closest ranks (numpy's default); 0 for no values.
double percentile(std::vector<double> v, double p);

// Over the visible pixels only, when `visible` (lens_mask.h) is given; 99 dB for equal images.
double psnr(const Rgba8Image& a, const Rgba8Image& b, std::span<const std::uint8_t> visible);

}  // namespace fg::bench
