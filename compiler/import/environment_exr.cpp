#include "environment_exr.h"

#include <cmath>
#include <exception>

#include <fmt/format.h>
#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

namespace fg {

std::optional<EnvironmentImage> read_environment_exr(const std::string& path, std::string& error) {
    try {
        Imf::RgbaInputFile file(path.c_str());
        const Imath::Box2i window = file.dataWindow();
        const long width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
        if (width < 2 || height < 1 || width > 8192 || height > 4096) {
            error = fmt::format("{}: the image is {}x{}; a lat-long environment needs 2 to 8192 columns and up to 4096 rows",
                                path, width, height);
            return std::nullopt;
        }
        Imf::Array2D<Imf::Rgba> pixels(height, width);
        file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, static_cast<std::size_t>(width));
        file.readPixels(window.min.y, window.max.y);
        EnvironmentImage image;
        image.width = static_cast<std::uint32_t>(width);
        image.height = static_cast<std::uint32_t>(height);
        image.rgba.reserve(static_cast<std::size_t>(width * height * 4));
        for (long y = 0; y < height; ++y)
            for (long x = 0; x < width; ++x) {
                const Imf::Rgba& p = pixels[y][x];
                for (half c : {p.r, p.g, p.b}) {
                    if (!c.isFinite()) {
                        error = fmt::format("{}: texel ({}, {}) is not a finite radiance ({})", path, x, y, float(c));
                        return std::nullopt;
                    }
                    image.rgba.push_back(c.isNegative() ? half(0.0f).bits() : c.bits());
                }
                image.rgba.push_back(half(1.0f).bits());
            }
        return image;
    } catch (const std::exception& e) {
        error = e.what();
        return std::nullopt;
    }
}

}  // namespace fg
