#include "scene_settings.h"

#include <cmath>
#include <fmt/format.h>
#include <set>

namespace fg {

namespace {

using nlohmann::json;

struct SceneReader {
    Diagnostics& diag;

    void check_keys(const json& j, const std::string& ptr, std::initializer_list<const char*> keys) {
        std::set<std::string> known(keys.begin(), keys.end());
        for (auto it = j.begin(); it != j.end(); ++it)
            if (!known.count(it.key()))
                diag.error(fmt::format("unknown scene setting \"{}\"", it.key()), ptr + "/" + it.key());
    }
    bool object(const json& j, const std::string& ptr) {
        if (j.is_object()) return true;
        diag.error("expected an object", ptr);
        return false;
    }
    void number(const json& j, const char* key, const std::string& ptr, double& out, double lo, double hi) {
        if (!j.contains(key)) return;
        const auto& v = j[key];
        std::string p = ptr + "/" + key;
        if (!v.is_number() || !std::isfinite(v.get<double>())) {
            diag.error("expected a finite number", p);
            return;
        }
        double x = v.get<double>();
        if (x < lo || x > hi) {
            diag.error(fmt::format("{} is out of range [{}, {}]", x, lo, hi), p);
            return;
        }
        out = x;
    }
    void vec3(const json& j, const char* key, const std::string& ptr, glm::dvec3& out, double lo = -1e9,
              double hi = 1e9) {
        if (!j.contains(key)) return;
        const auto& v = j[key];
        std::string p = ptr + "/" + key;
        if (v.is_number() && std::isfinite(v.get<double>())) {
            out = glm::dvec3(v.get<double>());
            return;
        }
        if (!v.is_array() || v.size() != 3) {
            diag.error("expected an array of 3 numbers", p);
            return;
        }
        glm::dvec3 r;
        for (int i = 0; i < 3; ++i) {
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) || v[i].get<double>() < lo ||
                v[i].get<double>() > hi) {
                diag.error(fmt::format("component {} must be a finite number in [{}, {}]", i, lo, hi),
                           fmt::format("{}/{}", p, i));
                return;
            }
            r[i] = v[i].get<double>();
        }
        out = r;
    }
};

}  // namespace

SceneSettings parse_scene_settings(const json* jp, const std::string& ptr, Diagnostics& diag) {
    SceneSettings s;
    if (!jp) return s;
    SceneReader r{diag};
    const json& j = *jp;
    if (!r.object(j, ptr)) return s;
    r.check_keys(j, ptr, {"camera", "light", "albedo", "background", "fog", "glow", "vignette", "foveation", "bounds",
                          "max_distance", "exposure", "scale", "locomotion", "step_factor", "precision"});
    if (j.contains("camera") && r.object(j["camera"], ptr + "/camera")) {
        const auto& c = j["camera"];
        std::string p = ptr + "/camera";
        r.check_keys(c, p, {"position", "target", "up", "fov_deg"});
        r.vec3(c, "position", p, s.camera.position);
        r.vec3(c, "target", p, s.camera.target);
        r.vec3(c, "up", p, s.camera.up);
        r.number(c, "fov_deg", p, s.camera.fov_deg, 10.0, 170.0);
        if (s.camera.position == s.camera.target) diag.error("camera position and target coincide", p + "/target");
    }
    if (j.contains("light") && r.object(j["light"], ptr + "/light")) {
        const auto& l = j["light"];
        std::string p = ptr + "/light";
        r.check_keys(l, p, {"direction", "color", "ambient", "sss_color", "rim_color"});
        r.vec3(l, "direction", p, s.light.direction);
        r.vec3(l, "color", p, s.light.color, 0.0, 1e4);
        r.vec3(l, "ambient", p, s.light.ambient, 0.0, 1e4);
        r.vec3(l, "sss_color", p, s.light.sss_color, 0.0, 1e4);
        r.vec3(l, "rim_color", p, s.light.rim_color, 0.0, 1e4);
        double len = glm::length(s.light.direction);
        if (len < 1e-9) diag.error("light direction has zero length", p + "/direction");
        else s.light.direction /= len;
    }
    r.vec3(j, "albedo", ptr, s.albedo, 0.0, 1e4);
    if (j.contains("background")) {
        const auto& b = j["background"];
        std::string p = ptr + "/background";
        if (b.is_array() || b.is_number()) {
            r.vec3(j, "background", ptr, s.background.top, 0.0, 1e4);
            s.background.bottom = s.background.top;
        } else if (r.object(b, p)) {
            r.check_keys(b, p, {"top", "bottom"});
            r.vec3(b, "top", p, s.background.top, 0.0, 1e4);
            s.background.bottom = s.background.top;
            r.vec3(b, "bottom", p, s.background.bottom, 0.0, 1e4);
        }
    }
    if (j.contains("fog") && r.object(j["fog"], ptr + "/fog")) {
        const auto& f = j["fog"];
        std::string p = ptr + "/fog";
        r.check_keys(f, p, {"color", "density"});
        SceneSettings::Fog fog;
        r.vec3(f, "color", p, fog.color, 0.0, 1e4);
        r.number(f, "density", p, fog.density, 0.0, 1e6);
        s.fog = fog;
    }
    if (j.contains("glow") && r.object(j["glow"], ptr + "/glow")) {
        const auto& g = j["glow"];
        std::string p = ptr + "/glow";
        r.check_keys(g, p, {"color", "intensity", "falloff"});
        SceneSettings::Glow glow;
        r.vec3(g, "color", p, glow.color, 0.0, 1e4);
        r.number(g, "intensity", p, glow.intensity, 0.0, 1e4);
        r.number(g, "falloff", p, glow.falloff, 1e-9, 1e6);
        s.glow = glow;
    }
    if (j.contains("vignette") && r.object(j["vignette"], ptr + "/vignette")) {
        std::string p = ptr + "/vignette";
        r.check_keys(j["vignette"], p, {"strength"});
        SceneSettings::Vignette v;
        r.number(j["vignette"], "strength", p, v.strength, 0.0, 1.0);
        s.vignette = v;
    }
    if (j.contains("foveation") && r.object(j["foveation"], ptr + "/foveation")) {
        std::string p = ptr + "/foveation";
        r.check_keys(j["foveation"], p, {"inner_radius", "blend"});
        SceneSettings::Foveation f;
        r.number(j["foveation"], "inner_radius", p, f.inner_radius, 0.05, 1.0);
        r.number(j["foveation"], "blend", p, f.blend, 0.0, 0.5);
        s.foveation = f;
    }
    if (j.contains("bounds") && r.object(j["bounds"], ptr + "/bounds")) {
        std::string p = ptr + "/bounds";
        r.check_keys(j["bounds"], p, {"center", "radius"});
        r.vec3(j["bounds"], "center", p, s.bounds_center);
        r.number(j["bounds"], "radius", p, s.bounds_radius, 1e-9, 1e9);
    }
    r.number(j, "max_distance", ptr, s.max_distance, 1e-6, 1e9);
    r.number(j, "exposure", ptr, s.exposure, 0.0, 1e4);
    r.number(j, "scale", ptr, s.world_scale, 1e-12, 1e12);
    r.number(j, "step_factor", ptr, s.step_factor, 0.05, 1.0);
    if (j.contains("precision")) {
        const auto& v = j["precision"];
        if (v == "float" || v == "double") s.double_precision = v == "double";
        else diag.error("expected \"float\" or \"double\"", ptr + "/precision");
    }
    if (j.contains("locomotion")) {
        if (r.object(j["locomotion"], ptr + "/locomotion")) s.locomotion = j["locomotion"];
    }
    return s;
}

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
    j["albedo"] = v(s.albedo);
    j["background"] = {{"top", v(s.background.top)}, {"bottom", v(s.background.bottom)}};
    if (s.fog) j["fog"] = {{"color", v(s.fog->color)}, {"density", s.fog->density}};
    if (s.glow) j["glow"] = {{"color", v(s.glow->color)}, {"intensity", s.glow->intensity}, {"falloff", s.glow->falloff}};
    if (s.vignette) j["vignette"] = {{"strength", s.vignette->strength}};
    if (s.foveation) j["foveation"] = {{"inner_radius", s.foveation->inner_radius}, {"blend", s.foveation->blend}};
    j["bounds"] = {{"center", v(s.bounds_center)}, {"radius", s.bounds_radius}};
    j["max_distance"] = s.max_distance;
    j["exposure"] = s.exposure;
    j["scale"] = s.world_scale;
    j["step_factor"] = s.step_factor;
    if (s.double_precision) j["precision"] = "double";
    j["locomotion"] = s.locomotion;
    return j;
}

}  // namespace fg
