#pragma once
// Scene settings of a graph ("scene": {...}): camera start, light, background and the post
// effects. Present blocks turn effects on (fog, glow, vignette, foveation); their values become
// uniforms, so editing them never recompiles. The compiler decodes them from the graph, the pack
// reader from the manifest; the runtime only ever sees this struct.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "common/diagnostics.h"

namespace fg {

// The limits of flight through the scene ("locomotion"; runtime/locomotion/locomotion.h).
struct LocomotionSettings {
    double speed_per_distance = 1.0;   // 1/s: speed = this * distance to the nearest surface
    double max_speed = 2.0;            // scene units per second per unit of world scale
    // Metres (scene units per unit of world scale): the closest the head gets. More than half the
    // distance between the eyes, so that neither eye enters the surface.
    double head_radius = 0.05;

    bool operator==(const LocomotionSettings&) const = default;
};

struct SceneSettings {
    struct Camera {
        glm::dvec3 position{0.0, 0.0, 3.0};
        glm::dvec3 target{0.0, 0.0, 0.0};
        glm::dvec3 up{0.0, 1.0, 0.0};
        double fov_deg = 90.0;
        bool operator==(const Camera&) const = default;
    } camera;
    struct Light {
        glm::dvec3 direction{0.57735026918962576, 0.57735026918962576, 0.57735026918962576};   // towards the light, unit length
        glm::dvec3 color{1.0, 0.95, 0.9};
        glm::dvec3 ambient{0.12, 0.14, 0.18};
        glm::dvec3 sss_color{1.0, 0.4, 0.25};
        glm::dvec3 rim_color{0.6, 0.8, 1.0};
        // Lights beside the main one ("auxiliary"), each lighting the surface by the same diffuse,
        // shadow and specular terms: directional, or a point whose colour is its intensity one scene
        // unit away (it falls off with the square of the distance).
        struct Auxiliary {
            std::optional<glm::dvec3> position;        // a point light; none: directional
            glm::dvec3 direction{0.0, 1.0, 0.0};       // towards a directional light
            glm::dvec3 color{1.0, 1.0, 1.0};
            bool operator==(const Auxiliary&) const = default;
        };
        static constexpr std::size_t kMaxAuxiliary = 4;
        std::vector<Auxiliary> auxiliary;
        bool operator==(const Light&) const = default;
    } light;
    glm::dvec3 albedo{0.8, 0.8, 0.8};                 // when the graph binds no albedo
    struct Background {
        glm::dvec3 top{0.02, 0.02, 0.03};
        glm::dvec3 bottom{0.02, 0.02, 0.03};
        bool operator==(const Background&) const = default;
    } background;
    struct Fog {
        glm::dvec3 color{0.05, 0.05, 0.08};
        double density = 0.1;                         // extinction per unit distance (at `height`)
        // Height fog: the density falls by e every 1 / height_falloff scene units above `height`
        // (and rises below it); 0: the same density everywhere.
        double height_falloff = 0.0;
        double height = 0.0;
        // Light shafts: the fog scatters this share of each light that reaches it, the main one, the
        // auxiliary ones and the environment (0: none), forward for anisotropy > 0
        // (Henyey-Greenstein). Shadowed while samples accumulate.
        double scatter = 0.0;
        double anisotropy = 0.0;
        bool operator==(const Fog&) const = default;
    };
    std::optional<Fog> fog;
    struct Glow {
        glm::dvec3 color{0.4, 0.7, 1.0};
        double intensity = 1.0;
        double falloff = 0.05;                        // distance at which glow drops to 1/e
        bool operator==(const Glow&) const = default;
    };
    std::optional<Glow> glow;
    // Light from all around: a lat-long (equirectangular) HDR image, or a uniform sky of `color`.
    // It is seen where rays miss and in reflections, and lights the surface diffusely.
    struct Environment {
        std::string image;                            // an OpenEXR file, relative to the graph's folder
        glm::dvec3 color{1.0, 1.0, 1.0};              // the image's tint, or the uniform sky's radiance
        double intensity = 1.0;
        double rotation_deg = 0.0;                    // turns the image about +y, counter-clockwise from above
        bool operator==(const Environment&) const = default;
    };
    std::optional<Environment> environment;
    struct Vignette {
        double strength = 0.4;
        bool operator==(const Vignette&) const = default;
    };
    std::optional<Vignette> vignette;
    struct Foveation {
        double inner_radius = 0.35;                   // of the half-diagonal, full resolution inside
        double blend = 0.15;
        bool operator==(const Foveation&) const = default;
    };
    std::optional<Foveation> foveation;
    glm::dvec3 bounds_center{0.0, 0.0, 0.0};
    double bounds_radius = 4.0;                       // rays leave the scene outside this sphere
    double max_distance = 100.0;                      // far limit of the march, in scene units
    double exposure = 1.0;
    double world_scale = 1.0;                         // initial viewer scale (locomotion)
    // "double": the scene's code runs in double precision around a camera-relative origin (deep zooms
    // of unit-size fractals); "float" everywhere else (docs/graph-format.md).
    bool double_precision = false;
    double step_factor = 1.0;                         // times 1 / Lipschitz bound: the march's step scale (fgc calibrate)
    double step_fraction = 1.0;                       // steps advance this share of the estimate; hit tests read all of it
    LocomotionSettings locomotion;

    bool has_background_gradient() const { return background.top != background.bottom; }
    bool operator==(const SceneSettings&) const = default;
};

// Parse "scene" (may be absent); unknown keys, wrong types and out-of-range values are reported
// under `pointer` (normally "/scene").
SceneSettings parse_scene_settings(const nlohmann::json* j, const std::string& pointer, Diagnostics& diag);
nlohmann::json scene_settings_to_json(const SceneSettings& s);

// How many times parse_scene_settings has run in this process: tests hold the runtime to decoding
// a pack's scene once, when the pack is read.
std::uint64_t scene_settings_parse_count();

}  // namespace fg
