#include "aov_images.h"

#include <array>

namespace fg {

std::span<const AovImage> aov_images() {
    static constexpr std::array<AovImage, 6> images{{
        {"fg_beauty", "beauty", ImageFormat::RGBA16F, "HDR beauty before the tone map"},
        {"fg_position", "position", ImageFormat::RGBA32F, "world position, camera depth in metres"},
        {"fg_normal", "normal", ImageFormat::RGBA16F, "normal, AO"},
        {"fg_albedo", "albedo", ImageFormat::RGBA16F, "albedo, diffuse factor"},
        {"fg_trap", "trap", ImageFormat::RGBA16F, "orbit trap"},
        {"fg_light", "light", ImageFormat::RGBA16F, "specular reflectance, shadow"},
    }};
    return images;
}

std::string aov_image_name(const AovImage& image, const std::string& eye) {
    return std::string("aov.") + image.name + "." + eye;
}

}  // namespace fg
