#include "effects.h"

#include <array>

namespace fg {

namespace {
constexpr std::array<std::string_view, static_cast<std::size_t>(Effect::Count)> kNames{
    "normals", "diffuse", "ao", "sss", "rim", "palette", "trap",
    "emission", "fog", "glow", "vignette", "background_gradient", "foveation", "shadow", "specular", "reflection", "lights", "environment", "refraction", "volume"};
}

std::string_view effect_name(Effect e) { return kNames[static_cast<std::size_t>(e)]; }

std::optional<Effect> parse_effect(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return static_cast<Effect>(i);
    return std::nullopt;
}

std::vector<std::string> EffectSet::names() const {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (has(static_cast<Effect>(i))) out.emplace_back(kNames[i]);
    return out;
}

}  // namespace fg
