#include "scene_settings.h"

#include <atomic>
#include <cmath>

#include "common/json_fields.h"

namespace fg {

namespace {

using nlohmann::json;

std::atomic<std::uint64_t> parse_count{0};

const NumberRange kCoordinate{-1e9, 1e9};
const NumberRange kColour{0.0, 1e4};

// Scene vectors may be written as one number for all three components (a grey, a uniform scale).
struct SceneReader : JsonFieldReader {
    using JsonFieldReader::JsonFieldReader;

    void vector(const json& object, const char* key, const std::string& ptr, glm::dvec3& out,
                NumberRange range = kCoordinate) {
        const json* v = find(object, key);
        if (!v) return;
        double x = 0.0;
        if (!v->is_number()) read(*v, field_pointer(ptr, key), out, range);
        else if (read(*v, field_pointer(ptr, key), x, range)) out = glm::dvec3(x);
    }
    // A block of settings: an object whose keys are all known, or nullptr (reported when it is no object).
    const json* block(const json& scene, const char* key, const std::string& ptr,
                      std::initializer_list<std::string_view> known) {
        const json* b = object_field(scene, key, ptr);
        if (b) unknown_keys(*b, field_pointer(ptr, key), known, "scene setting");
        return b;
    }
};

// Each a point ("position") or directional ("direction") light with its colour.
std::vector<SceneSettings::Light::Auxiliary> auxiliary_lights(SceneReader& r, const json& list, const std::string& ptr) {
    std::vector<SceneSettings::Light::Auxiliary> lights;
    if (list.size() > SceneSettings::Light::kMaxAuxiliary)
        r.error("at most " + std::to_string(SceneSettings::Light::kMaxAuxiliary) + " auxiliary lights", ptr);
    for (std::size_t i = 0; i < list.size() && i < SceneSettings::Light::kMaxAuxiliary; ++i) {
        const std::string p = ptr + "/" + std::to_string(i);
        if (!r.is_object(list[i], p)) continue;
        r.unknown_keys(list[i], p, {"position", "direction", "color"}, "light setting");
        SceneSettings::Light::Auxiliary light;
        const bool point = SceneReader::find(list[i], "position") != nullptr;
        if (point == (SceneReader::find(list[i], "direction") != nullptr)) {
            r.error("a light has either a position (a point light) or a direction (a directional light)", p);
            continue;
        }
        if (point) r.vector(list[i], "position", p, light.position.emplace());
        r.vector(list[i], "direction", p, light.direction);
        r.vector(list[i], "color", p, light.color, kColour);
        double len = glm::length(light.direction);
        if (len < 1e-9) r.error("light direction has zero length", p + "/direction");
        else if (std::abs(len - 1.0) > 1e-12) light.direction /= len;
        lights.push_back(light);
    }
    return lights;
}

}  // namespace

SceneSettings parse_scene_settings(const json* jp, const std::string& ptr, Diagnostics& diag) {
    ++parse_count;
    SceneSettings s;
    if (!jp) return s;
    SceneReader r(diag);
    const json& j = *jp;
    if (!r.is_object(j, ptr)) return s;
    r.unknown_keys(j, ptr, {"camera", "light", "albedo", "background", "fog", "glow", "environment", "vignette", "foveation", "bounds",
                            "max_distance", "exposure", "scale", "locomotion", "step_factor", "step_fraction", "precision"},
                   "scene setting");
    if (const json* c = r.block(j, "camera", ptr, {"position", "target", "up", "fov_deg"})) {
        std::string p = ptr + "/camera";
        r.vector(*c, "position", p, s.camera.position);
        r.vector(*c, "target", p, s.camera.target);
        r.vector(*c, "up", p, s.camera.up);
        r.optional(*c, "fov_deg", p, s.camera.fov_deg, NumberRange{10.0, 170.0});
        if (s.camera.position == s.camera.target) r.error("camera position and target coincide", p + "/target");
    }
    if (const json* l = r.block(j, "light", ptr, {"direction", "color", "ambient", "sss_color", "rim_color", "auxiliary"})) {
        std::string p = ptr + "/light";
        r.vector(*l, "direction", p, s.light.direction);
        r.vector(*l, "color", p, s.light.color, kColour);
        r.vector(*l, "ambient", p, s.light.ambient, kColour);
        r.vector(*l, "sss_color", p, s.light.sss_color, kColour);
        r.vector(*l, "rim_color", p, s.light.rim_color, kColour);
        // A unit direction is left as it is, so that decoding what scene_settings_to_json wrote gives
        // back the very same settings (the pack reader decodes what the compiler encoded).
        double len = glm::length(s.light.direction);
        if (len < 1e-9) r.error("light direction has zero length", p + "/direction");
        else if (std::abs(len - 1.0) > 1e-12) s.light.direction /= len;
        if (const json* a = r.array_field(*l, "auxiliary", p)) s.light.auxiliary = auxiliary_lights(r, *a, p + "/auxiliary");
    }
    r.vector(j, "albedo", ptr, s.albedo, kColour);
    if (const json* b = JsonFieldReader::find(j, "background")) {
        std::string p = ptr + "/background";
        if (!b->is_object()) {
            r.vector(j, "background", ptr, s.background.top, kColour);
            s.background.bottom = s.background.top;
        } else {
            r.unknown_keys(*b, p, {"top", "bottom"}, "scene setting");
            r.vector(*b, "top", p, s.background.top, kColour);
            s.background.bottom = s.background.top;
            r.vector(*b, "bottom", p, s.background.bottom, kColour);
        }
    }
    if (const json* f = r.block(j, "fog", ptr, {"color", "density", "height_falloff", "height", "scatter", "anisotropy"})) {
        std::string p = ptr + "/fog";
        SceneSettings::Fog fog;
        r.vector(*f, "color", p, fog.color, kColour);
        r.optional(*f, "density", p, fog.density, NumberRange{0.0, 1e6});
        r.optional(*f, "height_falloff", p, fog.height_falloff, NumberRange{0.0, 1e6});
        r.optional(*f, "height", p, fog.height);
        r.optional(*f, "scatter", p, fog.scatter, NumberRange{0.0, 1e3});
        r.optional(*f, "anisotropy", p, fog.anisotropy, NumberRange{-0.95, 0.95});
        s.fog = fog;
    }
    if (const json* g = r.block(j, "glow", ptr, {"color", "intensity", "falloff"})) {
        std::string p = ptr + "/glow";
        SceneSettings::Glow glow;
        r.vector(*g, "color", p, glow.color, kColour);
        r.optional(*g, "intensity", p, glow.intensity, NumberRange{0.0, 1e4});
        r.optional(*g, "falloff", p, glow.falloff, NumberRange{1e-9, 1e6});
        s.glow = glow;
    }
    if (const json* e = r.block(j, "environment", ptr, {"image", "color", "intensity", "rotation_deg"})) {
        std::string p = ptr + "/environment";
        SceneSettings::Environment env;
        r.optional(*e, "image", p, env.image);
        r.vector(*e, "color", p, env.color, kColour);
        r.optional(*e, "intensity", p, env.intensity, NumberRange{0.0, 1e6});
        r.optional(*e, "rotation_deg", p, env.rotation_deg, NumberRange{-360.0, 360.0});
        s.environment = env;
    }
    if (const json* v = r.block(j, "vignette", ptr, {"strength"})) {
        SceneSettings::Vignette vignette;
        r.optional(*v, "strength", ptr + "/vignette", vignette.strength, NumberRange{0.0, 1.0});
        s.vignette = vignette;
    }
    if (const json* f = r.block(j, "foveation", ptr, {"inner_radius", "blend"})) {
        std::string p = ptr + "/foveation";
        SceneSettings::Foveation foveation;
        r.optional(*f, "inner_radius", p, foveation.inner_radius, NumberRange{0.05, 1.0});
        r.optional(*f, "blend", p, foveation.blend, NumberRange{0.0, 0.5});
        s.foveation = foveation;
    }
    if (const json* b = r.block(j, "bounds", ptr, {"center", "radius"})) {
        std::string p = ptr + "/bounds";
        r.vector(*b, "center", p, s.bounds_center);
        r.optional(*b, "radius", p, s.bounds_radius, NumberRange{1e-9, 1e9});
    }
    r.optional(j, "max_distance", ptr, s.max_distance, NumberRange{1e-6, 1e9});
    r.optional(j, "exposure", ptr, s.exposure, NumberRange{0.0, 1e4});
    r.optional(j, "scale", ptr, s.world_scale, NumberRange{1e-12, 1e12});
    r.optional(j, "step_factor", ptr, s.step_factor, NumberRange{0.05, 1.0});
    r.optional(j, "step_fraction", ptr, s.step_fraction, NumberRange{0.01, 1.0});
    std::string precision;
    if (r.optional(j, "precision", ptr, precision, Choices{"float", "double"}))
        s.double_precision = precision == "double";
    if (const json* l = r.block(j, "locomotion", ptr, {"speed_per_distance", "max_speed", "head_radius"})) {
        std::string p = ptr + "/locomotion";
        r.optional(*l, "speed_per_distance", p, s.locomotion.speed_per_distance, NumberRange::positive());
        r.optional(*l, "max_speed", p, s.locomotion.max_speed, NumberRange::positive());
        r.optional(*l, "head_radius", p, s.locomotion.head_radius, NumberRange::positive());
    }
    return s;
}

std::uint64_t scene_settings_parse_count() { return parse_count.load(); }

json scene_settings_to_json(const SceneSettings& s) {
    auto v = [](const glm::dvec3& x) { return json::array({x.x, x.y, x.z}); };
    json j;
    j["camera"] = {{"position", v(s.camera.position)},
                   {"target", v(s.camera.target)},
                   {"up", v(s.camera.up)},
                   {"fov_deg", s.camera.fov_deg}};
    j["light"] = {{"direction", v(s.light.direction)},   {"color", v(s.light.color)},
                  {"ambient", v(s.light.ambient)},       {"sss_color", v(s.light.sss_color)},
                  {"rim_color", v(s.light.rim_color)}};
    for (const auto& a : s.light.auxiliary) {
        json light = {{"color", v(a.color)}};
        if (a.position) light["position"] = v(*a.position);
        else light["direction"] = v(a.direction);
        j["light"]["auxiliary"].push_back(light);
    }
    j["albedo"] = v(s.albedo);
    j["background"] = {{"top", v(s.background.top)}, {"bottom", v(s.background.bottom)}};
    if (s.fog) {
        j["fog"] = {{"color", v(s.fog->color)}, {"density", s.fog->density}};
        if (s.fog->height_falloff != 0.0) j["fog"].update({{"height_falloff", s.fog->height_falloff}, {"height", s.fog->height}});
        if (s.fog->scatter != 0.0) j["fog"].update({{"scatter", s.fog->scatter}, {"anisotropy", s.fog->anisotropy}});
    }
    if (s.glow) j["glow"] = {{"color", v(s.glow->color)}, {"intensity", s.glow->intensity}, {"falloff", s.glow->falloff}};
    if (s.environment) {
        const auto& e = *s.environment;
        j["environment"] = {{"color", v(e.color)}, {"intensity", e.intensity}, {"rotation_deg", e.rotation_deg}};
        if (!e.image.empty()) j["environment"]["image"] = e.image;
    }
    if (s.vignette) j["vignette"] = {{"strength", s.vignette->strength}};
    if (s.foveation) j["foveation"] = {{"inner_radius", s.foveation->inner_radius}, {"blend", s.foveation->blend}};
    j["bounds"] = {{"center", v(s.bounds_center)}, {"radius", s.bounds_radius}};
    j["max_distance"] = s.max_distance;
    j["exposure"] = s.exposure;
    j["scale"] = s.world_scale;
    j["step_factor"] = s.step_factor;
    if (s.step_fraction != 1.0) j["step_fraction"] = s.step_fraction;
    if (s.double_precision) j["precision"] = "double";
    j["locomotion"] = {{"speed_per_distance", s.locomotion.speed_per_distance},
                       {"max_speed", s.locomotion.max_speed},
                       {"head_radius", s.locomotion.head_radius}};
    return j;
}

}  // namespace fg
