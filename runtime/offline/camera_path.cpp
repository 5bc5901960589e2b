#include "camera_path.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>

namespace fg {

namespace {

double eased(Ease e, double s) {
    switch (e) {
        case Ease::Linear: return s;
        case Ease::In: return s * s;
        case Ease::Out: return s * (2.0 - s);
        case Ease::InOut: return s * s * (3.0 - 2.0 * s);
    }
    return s;
}

bool read_vec3(const nlohmann::json& j, const std::string& ptr, glm::dvec3& out, Diagnostics& diag) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number()) {
        diag.error("expected [x, y, z] numbers", ptr);
        return false;
    }
    out = {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
    if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z)) {
        diag.error("expected finite numbers", ptr);
        return false;
    }
    return true;
}

// Uniform Catmull-Rom through p1 (s = 0) and p2 (s = 1), with the outer keys as tangent guides.
glm::dvec3 catmull_rom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3, double s) {
    double s2 = s * s, s3 = s2 * s;
    return 0.5 * ((2.0 * p1) + (-p0 + p2) * s + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * s2 + (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * s3);
}

}  // namespace

std::optional<CameraPath> CameraPath::parse(const nlohmann::json& j, double default_world_scale, Diagnostics& diag) {
    std::size_t errors = diag.error_count();
    if (!j.is_object()) {
        diag.error("a camera path is a JSON object", "");
        return std::nullopt;
    }
    if (j.value("format", "") != "fractograph-camera-path")
        diag.error("expected \"format\": \"fractograph-camera-path\"", "/format");
    if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<int>() != 1)
        diag.error("this fgplay reads camera path version 1", "/version");
    CameraPath path;
    if (j.contains("fps")) {
        if (!j["fps"].is_number() || !(j["fps"].get<double>() > 0.0) || j["fps"].get<double>() > 10000.0)
            diag.error("fps must be a number in (0, 10000]", "/fps");
        else
            path.fps_ = j["fps"].get<double>();
    }
    if (j.contains("interpolation")) {
        std::string s = j["interpolation"].is_string() ? j["interpolation"].get<std::string>() : "";
        if (s == "smooth" || s == "linear") path.smooth_ = s == "smooth";
        else diag.error("interpolation is \"smooth\" or \"linear\"", "/interpolation");
    }
    if (!j.contains("keyframes") || !j["keyframes"].is_array() || j["keyframes"].empty()) {
        diag.error("expected a non-empty array of keyframes", "/keyframes");
        return std::nullopt;
    }
    const auto& keys = j["keyframes"];
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const auto& k = keys[i];
        std::string ptr = fmt::format("/keyframes/{}", i);
        if (!k.is_object()) {
            diag.error("a keyframe is an object", ptr);
            continue;
        }
        CameraKey key;
        key.world_scale = default_world_scale;
        if (!k.contains("time") || !k["time"].is_number() || !std::isfinite(k["time"].get<double>()))
            diag.error("expected a time in seconds", ptr + "/time");
        else
            key.time = k["time"].get<double>();
        if (!path.keys_.empty() && key.time <= path.keys_.back().time)
            diag.error(fmt::format("times must increase: {} follows {}", key.time, path.keys_.back().time), ptr + "/time");
        bool position_ok = k.contains("position") && read_vec3(k["position"], ptr + "/position", key.position, diag);
        if (!k.contains("position")) diag.error("expected a position [x, y, z]", ptr + "/position");
        bool has_target = k.contains("target"), has_quat = k.contains("orientation");
        if (has_target == has_quat)
            diag.error("give either a target [x, y, z] or an orientation [w, x, y, z]", ptr);
        if (has_target) {
            glm::dvec3 t;
            if (read_vec3(k["target"], ptr + "/target", t, diag)) {
                if (position_ok && glm::length(t - key.position) < 1e-12) diag.error("the target is at the position", ptr + "/target");
                key.target = t;
            }
            if (k.contains("up") && read_vec3(k["up"], ptr + "/up", key.up, diag) && glm::length(key.up) < 1e-12)
                diag.error("up must not be zero", ptr + "/up");
        }
        if (has_quat) {
            const auto& q = k["orientation"];
            bool ok = q.is_array() && q.size() == 4;
            for (std::size_t c = 0; ok && c < 4; ++c) ok = q[c].is_number() && std::isfinite(q[c].get<double>());
            glm::dquat quat(ok ? q[0].get<double>() : 0.0, ok ? q[1].get<double>() : 0.0, ok ? q[2].get<double>() : 0.0,
                            ok ? q[3].get<double>() : 0.0);
            if (!ok || glm::length(quat) < 1e-9) diag.error("expected a non-zero quaternion [w, x, y, z]", ptr + "/orientation");
            else key.orientation = glm::normalize(quat);
        }
        if (k.contains("world_scale")) {
            if (!k["world_scale"].is_number() || !(k["world_scale"].get<double>() > 0.0) ||
                !std::isfinite(k["world_scale"].get<double>()))
                diag.error("world_scale must be a positive number", ptr + "/world_scale");
            else
                key.world_scale = k["world_scale"].get<double>();
        }
        if (k.contains("ease")) {
            std::string e = k["ease"].is_string() ? k["ease"].get<std::string>() : "";
            if (e == "linear") key.ease = Ease::Linear;
            else if (e == "in") key.ease = Ease::In;
            else if (e == "out") key.ease = Ease::Out;
            else if (e == "in-out") key.ease = Ease::InOut;
            else diag.error("ease is \"linear\", \"in\", \"out\" or \"in-out\"", ptr + "/ease");
        }
        for (const auto& [name, _] : k.items())
            if (name != "time" && name != "position" && name != "target" && name != "up" && name != "orientation" &&
                name != "world_scale" && name != "ease")
                diag.error(fmt::format("unknown keyframe field \"{}\"", name), ptr + "/" + name);
        if (key.target) key.orientation = look_at(key.position, *key.target, key.up).orientation;
        path.keys_.push_back(key);
    }
    if (diag.error_count() > errors) return std::nullopt;
    return path;
}

std::optional<CameraPath> CameraPath::load(const std::string& file, double default_world_scale, Diagnostics& diag) {
    std::ifstream in(file);
    if (!in) {
        diag.error(fmt::format("cannot read {}", file));
        return std::nullopt;
    }
    try {
        return parse(nlohmann::json::parse(in), default_world_scale, diag);
    } catch (const nlohmann::json::parse_error& e) {
        diag.error(fmt::format("not valid JSON at byte {}: {}", e.byte, e.what()));
        return std::nullopt;
    }
}

int CameraPath::frame_count() const {
    double duration = keys_.back().time - keys_.front().time;
    return static_cast<int>(std::floor(duration * fps_ + 1e-9)) + 1;
}

CameraSample CameraPath::sample(int frame) const { return at(keys_.front().time + frame / fps_); }

CameraSample CameraPath::at(double time) const {
    CameraSample out;
    out.time = time;
    if (keys_.size() == 1 || time <= keys_.front().time) {
        const auto& k = time <= keys_.front().time ? keys_.front() : keys_.back();
        out.head = {k.position, k.orientation};
        out.world_scale = k.world_scale;
        return out;
    }
    std::size_t i = 0;
    while (i + 2 < keys_.size() && time >= keys_[i + 1].time) ++i;
    const CameraKey& a = keys_[i];
    const CameraKey& b = keys_[i + 1];
    double s = eased(a.ease, std::clamp((time - a.time) / (b.time - a.time), 0.0, 1.0));
    const CameraKey& before = i > 0 ? keys_[i - 1] : a;
    const CameraKey& after = i + 2 < keys_.size() ? keys_[i + 2] : b;
    auto curve = [&](const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
        return smooth_ ? catmull_rom(p0, p1, p2, p3, s) : glm::mix(p1, p2, s);
    };
    out.head.position = curve(before.position, a.position, b.position, after.position);
    if (a.target && b.target) {
        // Both keys look at a point: the point moves (on the same kind of curve), the camera follows it.
        glm::dvec3 target = curve(before.target.value_or(*a.target), *a.target, *b.target, after.target.value_or(*b.target));
        glm::dvec3 up = glm::mix(glm::normalize(a.up), glm::normalize(b.up), s);
        up = glm::length(up) > 1e-9 ? glm::normalize(up) : a.up;
        if (glm::length(target - out.head.position) > 1e-12) out.head.orientation = look_at(out.head.position, target, up).orientation;
        else out.head.orientation = glm::slerp(a.orientation, b.orientation, s);
    } else {
        out.head.orientation = glm::slerp(a.orientation, b.orientation, s);
    }
    // Scale is a zoom: interpolate its logarithm, so each second zooms by the same factor.
    out.world_scale = std::exp(glm::mix(std::log(a.world_scale), std::log(b.world_scale), s));
    return out;
}

}  // namespace fg
