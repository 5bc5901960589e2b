#pragma once
// What both benchmarks measure frames with: robust statistics of per-frame figures, and the PSNR of
// an image against the strict reference (frame/strict_reference.h).
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

}  // namespace fg::bench
