#include "swapchain_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace fgxrt {

namespace {

struct ColourFormat {
    VkFormat format;
    const char* name;
};

// Monado's order: deep formats first, then 8-bit sRGB, then 8-bit linear.
constexpr ColourFormat kColourFormats[] = {
    {VK_FORMAT_R16G16B16A16_SFLOAT, "R16G16B16A16_SFLOAT"}, {VK_FORMAT_R16G16B16A16_UNORM, "R16G16B16A16_UNORM"},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, "A2B10G10R10_UNORM_PACK32"}, {VK_FORMAT_B8G8R8A8_SRGB, "B8G8R8A8_SRGB"},
    {VK_FORMAT_R8G8B8A8_SRGB, "R8G8B8A8_SRGB"}, {VK_FORMAT_B8G8R8A8_UNORM, "B8G8R8A8_UNORM"},
    {VK_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM"}};

bool is_bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM; }
bool is_srgb(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_R8G8B8A8_SRGB; }
bool is_8bit_linear(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_R8G8B8A8_UNORM; }

double half_to_double(std::uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    double v = exponent == 0 ? std::ldexp(mantissa, -24)
               : exponent == 31 ? (mantissa ? NAN : INFINITY)
                                : std::ldexp(mantissa + 1024, exponent - 25);
    return (h & 0x8000) ? -v : v;
}

std::uint16_t u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }

double clamp01(double v) { return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0); }

}  // namespace

std::vector<VkFormat> offered_colour_formats() {
    std::vector<VkFormat> out;
    const char* only = std::getenv("FG_XR_TEST_COLOUR_FORMATS");
    if (!only || !*only) {
        for (const auto& f : kColourFormats) out.push_back(f.format);
        return out;
    }
    std::stringstream list(only);
    std::string name;
    while (std::getline(list, name, ','))
        for (const auto& f : kColourFormats)
            if (name == f.name) out.push_back(f.format);
    return out;
}

bool is_colour_format(VkFormat format) {
    return std::any_of(std::begin(kColourFormats), std::end(kColourFormats), [&](const ColourFormat& f) { return f.format == format; });
}

const char* colour_format_name(VkFormat format) {
    for (const auto& f : kColourFormats)
        if (f.format == format) return f.name;
    return "unexpected format";
}

std::uint32_t texel_bytes(VkFormat format) {
    return format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16B16A16_UNORM ? 8u : 4u;
}

double srgb_encode(double linear) {
    linear = clamp01(linear);
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
    encoded = clamp01(encoded);
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

std::array<double, 3> linear_rgb(VkFormat format, const std::uint8_t* t) {
    switch (format) {
        case VK_FORMAT_R16G16B16A16_SFLOAT:
            return {clamp01(half_to_double(u16(t))), clamp01(half_to_double(u16(t + 2))), clamp01(half_to_double(u16(t + 4)))};
        case VK_FORMAT_R16G16B16A16_UNORM: return {u16(t) / 65535.0, u16(t + 2) / 65535.0, u16(t + 4) / 65535.0};
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32: {
            std::uint32_t w = 0;
            std::memcpy(&w, t, 4);
            return {(w & 1023u) / 1023.0, ((w >> 10) & 1023u) / 1023.0, ((w >> 20) & 1023u) / 1023.0};
        }
        default: {
            const double r = (is_bgra(format) ? t[2] : t[0]) / 255.0, g = t[1] / 255.0, b = (is_bgra(format) ? t[0] : t[2]) / 255.0;
            if (is_srgb(format)) return {srgb_decode(r), srgb_decode(g), srgb_decode(b)};
            return {r, g, b};
        }
    }
}

std::vector<std::uint8_t> display_rgba(VkFormat format, const std::vector<std::uint8_t>& texels, std::size_t pixels) {
    std::vector<std::uint8_t> out(4 * pixels, 255);
    const std::uint32_t bytes = texel_bytes(format);
    if (texels.size() < pixels * bytes) return {};
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* t = &texels[i * bytes];
        if (is_srgb(format)) {   // already what the display shows
            out[4 * i] = is_bgra(format) ? t[2] : t[0];
            out[4 * i + 1] = t[1];
            out[4 * i + 2] = is_bgra(format) ? t[0] : t[2];
            continue;
        }
        const auto rgb = linear_rgb(format, t);
        for (int c = 0; c < 3; ++c) out[4 * i + c] = static_cast<std::uint8_t>(std::lround(255.0 * srgb_encode(rgb[c])));
    }
    return out;
}

ColourComparison compare_colour(VkFormat format, const std::vector<std::uint8_t>& texels, const std::uint8_t* png_rgba,
                                std::size_t pixels, double tolerance) {
    ColourComparison result;
    const std::uint32_t bytes = texel_bytes(format);
    if (!png_rgba || texels.size() < pixels * bytes) return result;
    result.compared = true;
    const bool own_linear_steps = is_8bit_linear(format);
    result.steps = own_linear_steps ? "8-bit linear levels" : "8-bit sRGB levels";
    for (std::size_t i = 0; i < pixels; ++i) {
        const auto rgb = linear_rgb(format, &texels[i * bytes]);
        double pixel_worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double png = png_rgba[4 * i + c] / 255.0;
            const double diff = own_linear_steps ? 255.0 * std::abs(rgb[c] - srgb_decode(png))
                                                 : 255.0 * std::abs(srgb_encode(rgb[c]) - png);
            pixel_worst = std::max(pixel_worst, diff);
        }
        result.worst = std::max(result.worst, pixel_worst);
        if (pixel_worst > tolerance + 1e-6) ++result.off;
    }
    return result;
}

ColourComparison compare_mean_colour(VkFormat format, const std::vector<std::uint8_t>& texels, std::size_t pixels,
                                     const std::uint8_t* png_rgba, std::size_t png_pixels, double tolerance) {
    ColourComparison result;
    const std::uint32_t bytes = texel_bytes(format);
    if (!png_rgba || pixels == 0 || png_pixels == 0 || texels.size() < pixels * bytes) return result;
    result.compared = true;
    result.steps = "8-bit sRGB levels of the mean";
    std::array<double, 3> shown{}, expected{};
    for (std::size_t i = 0; i < pixels; ++i) {
        const auto rgb = linear_rgb(format, &texels[i * bytes]);
        for (int c = 0; c < 3; ++c) shown[c] += rgb[c] / static_cast<double>(pixels);
    }
    for (std::size_t i = 0; i < png_pixels; ++i)
        for (int c = 0; c < 3; ++c) expected[c] += srgb_decode(png_rgba[4 * i + c] / 255.0) / static_cast<double>(png_pixels);
    for (int c = 0; c < 3; ++c) {
        const double diff = 255.0 * std::abs(srgb_encode(shown[c]) - srgb_encode(expected[c]));
        result.worst = std::max(result.worst, diff);
        if (diff > tolerance) ++result.off;
    }
    return result;
}

}  // namespace fgxrt
