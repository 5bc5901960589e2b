#pragma once
// The colour an application's swapchain texels stand for, read as the OpenXR specification says:
// an sRGB format holds sRGB-encoded values, every other format linear ones, which the compositor
// encodes for the display itself. The test runtime decodes each submitted image that way and
// compares it with the PNG fgplay wrote for the same frame, so a double encoding (display-ready
// bytes in a linear swapchain) shows as the lifted, washed-out image a real headset would show.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace fgxrt {

// The colour formats the test runtime offers, in its order of preference (Monado lists deep
// formats first); FG_XR_TEST_COLOUR_FORMATS=NAME,NAME offers only those.
std::vector<VkFormat> offered_colour_formats();
bool is_colour_format(VkFormat format);
const char* colour_format_name(VkFormat format);
std::uint32_t texel_bytes(VkFormat format);

double srgb_encode(double linear);   // [0, 1] -> [0, 1], the sRGB transfer function
double srgb_decode(double encoded);

// A texel's red, green and blue as linear light in [0, 1].
std::array<double, 3> linear_rgb(VkFormat format, const std::uint8_t* texel);
// What a display shows for `texels` (width * height texels of `format`): sRGB-encoded RGBA8.
std::vector<std::uint8_t> display_rgba(VkFormat format, const std::vector<std::uint8_t>& texels, std::size_t pixels);

struct ColourComparison {
    bool compared = false;          // false: the PNG is missing or of another size
    std::size_t off = 0;            // pixels with a channel more than `tolerance` steps away
    double worst = 0.0;             // in those steps
    std::string steps;              // what a step is: "8-bit sRGB levels" or "8-bit linear levels"
};

// Each texel against the PNG's colour written as the format should hold it. Formats that hold at
// least the PNG's precision everywhere (8-bit sRGB, 10 and 16 bits, half floats) are compared in
// the PNG's own 8-bit sRGB levels; 8-bit linear formats, which cannot hold its dark tones, in
// their own linear levels.
ColourComparison compare_colour(VkFormat format, const std::vector<std::uint8_t>& texels, const std::uint8_t* png_rgba,
                                std::size_t pixels, double tolerance);

// For an image scaled from the PNG's size (fgplay rendered smaller than the swapchain): the mean
// of each channel in linear light, which a linear blit keeps, compared in 8-bit sRGB levels;
// `off` is the number of channels further apart than `tolerance`.
ColourComparison compare_mean_colour(VkFormat format, const std::vector<std::uint8_t>& texels, std::size_t pixels,
                                     const std::uint8_t* png_rgba, std::size_t png_pixels, double tolerance);

}  // namespace fgxrt
