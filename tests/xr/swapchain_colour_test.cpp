// The test runtime reads swapchain colour as the OpenXR specification says, so a double encoding
// cannot pass for the PNG's colour.
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "swapchain_colour.h"

namespace fgxrt {
namespace {

// A PNG-like RGBA8 image with every 8-bit value in every channel.
std::vector<std::uint8_t> every_level() {
    std::vector<std::uint8_t> png;
    for (int v = 0; v < 256; ++v) png.insert(png.end(), {std::uint8_t(v), std::uint8_t(255 - v), std::uint8_t((v * 7) % 256), 255});
    return png;
}

std::uint16_t to_half(double v) {
    if (v < std::ldexp(1.0, -14)) return static_cast<std::uint16_t>(std::lround(std::ldexp(v, 24)));
    int e = static_cast<int>(std::floor(std::log2(v)));
    long mantissa = std::lround((std::ldexp(v, -e) - 1.0) * 1024.0);
    if (mantissa == 1024) {
        mantissa = 0;
        ++e;
    }
    return static_cast<std::uint16_t>(((e + 15) << 10) | mantissa);
}

TEST(SwapchainColour, TheSrgbTransferFunctionRoundTripsEveryLevel) {
    for (int v = 0; v < 256; ++v) EXPECT_NEAR(255.0 * srgb_encode(srgb_decode(v / 255.0)), v, 1e-9);
}

TEST(SwapchainColour, ThePngBytesInAnSrgbSwapchainAreThePngColour) {
    const auto png = every_level();
    const ColourComparison c = compare_colour(VK_FORMAT_R8G8B8A8_SRGB, png, png.data(), 256, 2.0);
    EXPECT_TRUE(c.compared);
    EXPECT_EQ(c.off, 0u);
    EXPECT_NEAR(c.worst, 0.0, 1e-9);
    EXPECT_EQ(display_rgba(VK_FORMAT_R8G8B8A8_SRGB, png, 256), png);
}

TEST(SwapchainColour, ABgraSwapchainIsReadWithItsChannelsInTheirPlaces) {
    const auto png = every_level();
    auto bgra = png;
    for (std::size_t i = 0; i < bgra.size(); i += 4) std::swap(bgra[i], bgra[i + 2]);
    EXPECT_EQ(compare_colour(VK_FORMAT_B8G8R8A8_SRGB, bgra, png.data(), 256, 2.0).off, 0u);
    EXPECT_GT(compare_colour(VK_FORMAT_R8G8B8A8_SRGB, bgra, png.data(), 256, 2.0).off, 200u);
}

TEST(SwapchainColour, ThePngBytesInALinearSwapchainAreSeenDoubleEncoded) {
    // What fgplay did before: display-ready bytes into R8G8B8A8_UNORM. A conformant compositor
    // encodes them again: mid grey 128 shows as 188, the darks lift most.
    const auto png = every_level();
    const ColourComparison c = compare_colour(VK_FORMAT_R8G8B8A8_UNORM, png, png.data(), 256, 2.0);
    EXPECT_GT(c.off, 200u);
    EXPECT_GT(c.worst, 50.0);
    const auto shown = display_rgba(VK_FORMAT_R8G8B8A8_UNORM, png, 256);
    EXPECT_EQ(shown[4 * 128], 188);
}

TEST(SwapchainColour, LinearValuesOfThePngInAnEightBitLinearSwapchainAreWithinItsOwnSteps) {
    const auto png = every_level();
    std::vector<std::uint8_t> linear = png;
    for (std::size_t i = 0; i < png.size(); ++i)
        if (i % 4 != 3) linear[i] = static_cast<std::uint8_t>(std::lround(255.0 * srgb_decode(png[i] / 255.0)));
    const ColourComparison c = compare_colour(VK_FORMAT_R8G8B8A8_UNORM, linear, png.data(), 256, 2.0);
    EXPECT_EQ(c.off, 0u);
    EXPECT_LE(c.worst, 0.5 + 1e-9);
    EXPECT_EQ(c.steps, "8-bit linear levels");
}

TEST(SwapchainColour, LinearValuesOfThePngInAHalfFloatSwapchainAreThePngColour) {
    const auto png = every_level();
    std::vector<std::uint8_t> half(256 * 8);
    for (std::size_t i = 0; i < 256; ++i)
        for (int c = 0; c < 4; ++c) {
            const std::uint16_t h = to_half(c == 3 ? 1.0 : srgb_decode(png[4 * i + c] / 255.0));
            half[8 * i + 2 * c] = static_cast<std::uint8_t>(h & 0xff);
            half[8 * i + 2 * c + 1] = static_cast<std::uint8_t>(h >> 8);
        }
    const ColourComparison c = compare_colour(VK_FORMAT_R16G16B16A16_SFLOAT, half, png.data(), 256, 2.0);
    EXPECT_EQ(c.off, 0u);
    EXPECT_LT(c.worst, 0.5);
    EXPECT_EQ(c.steps, "8-bit sRGB levels");
}

TEST(SwapchainColour, AScaledImageIsJudgedByItsMeanColourInLinearLight) {
    const auto png = every_level();
    // Twice as many pixels, each PNG pixel twice: the same mean.
    std::vector<std::uint8_t> doubled;
    for (std::size_t i = 0; i < 256; ++i)
        for (int k = 0; k < 2; ++k) doubled.insert(doubled.end(), png.begin() + 4 * i, png.begin() + 4 * i + 4);
    EXPECT_EQ(compare_mean_colour(VK_FORMAT_R8G8B8A8_SRGB, doubled, 512, png.data(), 256, 2.0).off, 0u);
    EXPECT_GT(compare_mean_colour(VK_FORMAT_R8G8B8A8_UNORM, doubled, 512, png.data(), 256, 2.0).off, 0u);
}

}  // namespace
}  // namespace fgxrt
