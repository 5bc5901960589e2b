#pragma once
// What an offline frame is written as: an 8-bit PNG of the picture (the default), a 16-bit PNG of
// the same picture tone mapped from the HDR beauty, or an OpenEXR file with the picture's terms
// (exr_frame.h). The last two need the AOV pass.
#include <cstdint>
#include <string>
#include <vector>

#include "display_transform.h"
#include "exr_frame.h"
#include "frame/dispatch_tiles.h"
#include "frame/image_output.h"

namespace fg {

enum class OutputFormat { Png, Png16, Exr };
bool parse_output_format(const std::string& text, OutputFormat& out);
const char* output_format_name(OutputFormat f);
const char* output_extension(OutputFormat f);
inline bool needs_aovs(OutputFormat f) { return f != OutputFormat::Png; }

// One eye's (or a mono panorama's) AOV images at the output size, in aov_images() order.
struct OfflineEye {
    std::string view;
    std::uint32_t width = 0, height = 0;
    std::vector<std::vector<std::byte>> aovs;
    ExrCamera camera;
    bool panorama = false;
};

// AOV images rendered `factor` x `factor` samples per pixel, at the output size: the channels that
// hold light box-filtered (the beauty, specular and shadow, the mirror bounce, AO: linear light or a
// share of it), the others taken from each pixel's central sample (a depth or a normal averaged
// across an edge belongs to no surface).
std::vector<std::vector<std::byte>> downsample_aovs(std::vector<std::vector<std::byte>> aovs,
                                                     std::uint32_t width, std::uint32_t height, std::uint32_t factor);

// Jittered samples of one eye (sample_accumulator.h): add_samples sums each sample's light channels
// (those downsample_aovs averages) in float, over the tiles `sampled` keeps (all without; `width`:
// the eye's); mean_samples writes the mean of each pixel's `counts` samples into the first sample's
// AOVs, whose other channels stay its own, as downsample_aovs keeps a central sample's.
using AovSums = std::vector<std::vector<float>>;   // per AOV image, a float per channel
void add_samples(AovSums& sums, const std::vector<std::vector<std::byte>>& aovs, const SampledTiles* sampled,
                 std::uint32_t width);
void mean_samples(std::vector<std::vector<std::byte>>& aovs, const AovSums& sums, const std::vector<std::uint32_t>& counts);

// The beauty tone mapped as the frame's own tone map does it (ACES fit; the beauty carries the
// exposure), in 16 bits per channel; eyes side by side, or top-bottom for ODS (`stacked`).
std::vector<std::uint8_t> encode_png16(const std::vector<OfflineEye>& eyes, bool stacked);

}  // namespace fg
