#include "image_output.h"

#include <algorithm>
#include <cstring>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO_UNUSED
#include <stb/stb_image_write.h>
#include <png.h>

namespace fg {

Rgba8Image rgba8_from_bytes(std::span<const std::byte> bytes, std::uint32_t width, std::uint32_t height) {
    Rgba8Image img{width, height, {}};
    img.pixels.resize(static_cast<std::size_t>(width) * height * 4);
    std::memcpy(img.pixels.data(), bytes.data(), std::min(bytes.size(), img.pixels.size()));
    return img;
}

Rgba8Image side_by_side(const Rgba8Image& left, const Rgba8Image& right) {
    Rgba8Image out{left.width + right.width, std::max(left.height, right.height), {}};
    out.pixels.assign(static_cast<std::size_t>(out.width) * out.height * 4, 0);
    for (std::uint32_t y = 0; y < out.height; ++y) {
        if (y < left.height)
            std::memcpy(&out.pixels[(static_cast<std::size_t>(y) * out.width) * 4],
                        &left.pixels[static_cast<std::size_t>(y) * left.width * 4], left.width * 4u);
        if (y < right.height)
            std::memcpy(&out.pixels[(static_cast<std::size_t>(y) * out.width + left.width) * 4],
                        &right.pixels[static_cast<std::size_t>(y) * right.width * 4], right.width * 4u);
    }
    return out;
}

bool write_png(const std::string& path, const Rgba8Image& image) {
    return stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4,
                          image.pixels.data(), static_cast<int>(image.width * 4)) != 0;
}

std::vector<std::uint8_t> encode_png(const Rgba8Image& image) {
    std::vector<std::uint8_t> out;
    auto append = [](void* context, void* data, int size) {
        auto* bytes = static_cast<std::uint8_t*>(data);
        static_cast<std::vector<std::uint8_t>*>(context)->insert(static_cast<std::vector<std::uint8_t>*>(context)->end(),
                                                                 bytes, bytes + size);
    };
    stbi_write_png_to_func(append, &out, static_cast<int>(image.width), static_cast<int>(image.height), 4,
                           image.pixels.data(), static_cast<int>(image.width * 4));
    return out;
}

// stb_image_write has no 16-bit PNG; libpng writes it.
bool write_depth_png16(const std::string& path, std::span<const float> depth, std::uint32_t width,
                       std::uint32_t height, float far) {
    std::vector<std::uint16_t> grey(static_cast<std::size_t>(width) * height);
    for (std::size_t i = 0; i < grey.size(); ++i) {
        float t = depth[i];
        grey[i] = t < 0.0f ? 0 : static_cast<std::uint16_t>(65535.0f * std::clamp(1.0f - t / far, 0.0f, 1.0f));
    }
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = width;
    image.height = height;
    image.format = PNG_FORMAT_LINEAR_Y;  // 16-bit grey
    bool ok = png_image_write_to_file(&image, path.c_str(), 0, grey.data(), 0, nullptr) != 0;
    png_image_free(&image);
    return ok;
}

}  // namespace fg
