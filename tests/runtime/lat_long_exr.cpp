#include "lat_long_exr.h"

#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>

#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>

namespace fg::test {

std::string write_lat_long_exr(const std::string& name, int width, int height,
                               const std::function<glm::dvec3(double u, double v)>& colour) {
    const auto path = std::filesystem::temp_directory_path() / fmt::format("fg_sky_{}_{}.exr", name, ::getpid());
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::dvec3 c = colour((x + 0.5) / width, (y + 0.5) / height);
            pixels[y][x] = Imf::Rgba(static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z), 1.0f);
        }
    Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_RGBA);
    file.setFrameBuffer(&pixels[0][0], 1, static_cast<std::size_t>(width));
    file.writePixels(height);
    return path.string();
}

}  // namespace fg::test
