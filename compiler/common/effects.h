#pragma once
// The effects a scene can use. The compiler finds which ones a graph needs (EffectSet analysis),
// emits code only for those and lists them in the pack; the runtime allocates images and runs
// passes only for those. One list, one place, like Filament's variant bits.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fg {

enum class Effect : std::uint32_t {
    Normals,             // finite-difference normals at the hit (4 or 6 taps)
    Diffuse,             // one-sample fake diffuse (estimateCosTheta)
    AmbientOcclusion,    // one-sample fake AO
    Subsurface,          // one-sample fake SSS
    Rim,                 // rim light
    Palette,             // cosine palette colouring
    OrbitTrap,           // orbit-trap colour from a fractal's trap output
    Emission,            // emissive surface term
    Fog,                 // homogeneous scattering fog (post)
    Glow,                // glow from the minimum distance along the ray (march + post)
    Vignette,            // comfort / look vignette (post)
    BackgroundGradient,  // two-colour sky instead of a flat background
    Foveation,           // half-resolution periphery, blended (scene asks for it)
    Shadow,              // the light's visibility, marched towards it (light.soft_shadow)
    Specular,            // specular highlights (light.specular)
    Reflection,          // one mirror bounce (light.reflection): the shade pass marches the reflected ray
    Lights,              // auxiliary lights (scene.light.auxiliary): the light's terms again for each
    Environment,         // light from a lat-long HDR image or a uniform sky (scene.environment)
    Refraction,          // glass (light.refraction): the shade pass bends the ray through the body and out
    Volume,              // a glowing medium drawn as nodes (volume_density, light.iteration_fog): marched along each eye ray
    Count
};

std::string_view effect_name(Effect e);
std::optional<Effect> parse_effect(std::string_view name);

class EffectSet {
public:
    void add(Effect e) { bits_ |= bit(e); }
    bool has(Effect e) const { return (bits_ & bit(e)) != 0; }
    std::uint32_t bits() const { return bits_; }
    std::vector<std::string> names() const;
    bool operator==(const EffectSet&) const = default;

private:
    static std::uint32_t bit(Effect e) { return 1u << static_cast<std::uint32_t>(e); }
    std::uint32_t bits_ = 0;
};

}  // namespace fg
