#pragma once
// Writing rendered frames: 8-bit colour as PNG, depth as 16-bit PNG (stb_image_write and
// libpng), and the side-by-side stereo pair.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace fg {

struct Rgba8Image {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> pixels;   // RGBA, rows top to bottom
};

Rgba8Image rgba8_from_bytes(std::span<const std::byte> bytes, std::uint32_t width, std::uint32_t height);
Rgba8Image side_by_side(const Rgba8Image& left, const Rgba8Image& right);
bool write_png(const std::string& path, const Rgba8Image& image);
// The same PNG in memory (a server sends it).
std::vector<std::uint8_t> encode_png(const Rgba8Image& image);
// Depth (distances, FG_MISS < 0) as a 16-bit grey PNG: near is bright, misses are black.
bool write_depth_png16(const std::string& path, std::span<const float> depth, std::uint32_t width,
                       std::uint32_t height, float far);

}  // namespace fg
