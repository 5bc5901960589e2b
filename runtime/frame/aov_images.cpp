#include "aov_images.h"

#include <array>

namespace fg {

std::span<const AovImage> aov_images() {
    static constexpr std::array<AovImage, 8> images{{
        {"fg_beauty", "beauty", ImageFormat::RGBA16F, "HDR beauty before the tone map"},
        {"fg_position", "position", ImageFormat::RGBA32F, "world position, camera depth in metres"},
        {"fg_normal", "normal", ImageFormat::RGBA16F, "normal, AO"},
        {"fg_albedo", "albedo", ImageFormat::RGBA16F, "albedo, diffuse factor"},
        {"fg_trap", "trap", ImageFormat::RGBA16F, "orbit trap"},
        {"fg_light", "light", ImageFormat::RGBA16F, "specular reflectance, shadow"},
        {"fg_reflection", "reflection", ImageFormat::RGBA16F, "the colour reflections add: the mirror bounce, the environment in the specular lobe"},
        {"fg_refraction", "refraction", ImageFormat::RGBA16F, "the colour the light through glass adds"},
    }};
    return images;
}

bool aov_image_needed(const AovImage& image, const EffectSet& effects) {
    const std::string_view name = image.name;
    if (name == "light") return effects.has(Effect::Shadow) || effects.has(Effect::Specular);
    if (name == "reflection") return effects.has(Effect::Reflection);
    if (name == "refraction") return effects.has(Effect::Refraction);
    return true;
}

std::string aov_image_name(const AovImage& image, const std::string& eye) {
    return std::string("aov.") + image.name + "." + eye;
}

}  // namespace fg
