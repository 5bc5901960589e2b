#include "camera_path.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>

#include "common/json_fields.h"

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

// Uniform Catmull-Rom through p1 (s = 0) and p2 (s = 1), with the outer keys as tangent guides.
glm::dvec3 catmull_rom(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3, double s) {
    double s2 = s * s, s3 = s2 * s;
    return 0.5 * ((2.0 * p1) + (-p0 + p2) * s + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * s2 + (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * s3);
}

double catmull_rom(double p0, double p1, double p2, double p3, double s) {
    return catmull_rom(glm::dvec3(p0), glm::dvec3(p1), glm::dvec3(p2), glm::dvec3(p3), s).x;
}

// `"power": 6.5` or `"tint": [1, 0.5, 0.2]`.
void read_param_keys(JsonFieldReader& r, const nlohmann::json& k, const std::string& ptr, CameraKey& key) {
    if (!k.contains("params")) return;
    const std::string at = ptr + "/params";
    if (!r.is_object(k["params"], at)) return;
    for (const auto& [name, value] : k["params"].items()) {
        const std::string field = at + "/" + name;
        std::vector<double> v(value.is_array() ? value.size() : 1);
        if (value.is_array() && (v.empty() || v.size() > 4)) {
            r.error("expected a number or 1 to 4 numbers", field);
            continue;
        }
        bool ok = value.is_array() ? r.read_numbers(value, field, v) : r.read(value, field, v[0]);
        if (ok) key.params[name] = v;
    }
}

}  // namespace

std::optional<CameraPath> CameraPath::parse(const nlohmann::json& j, double default_world_scale, Diagnostics& diag) {
    JsonFieldReader r(diag);
    if (!r.is_object(j, "")) return std::nullopt;
    r.unknown_keys(j, "", {"format", "version", "fps", "interpolation", "keyframes"});
    std::string format;
    r.required(j, "format", "", format, Choices{"fractograph-camera-path"});
    std::int64_t version = 0;
    if (r.required(j, "version", "", version) && version != 1) r.error("this fgplay reads camera path version 1", "/version");
    CameraPath path;
    r.optional(j, "fps", "", path.fps_, NumberRange{0.0, 10000.0, true});
    std::string interpolation;
    if (r.optional(j, "interpolation", "", interpolation, Choices{"smooth", "linear"})) path.smooth_ = interpolation == "smooth";
    const nlohmann::json* keys = r.array_field(j, "keyframes", "", true);
    if (!keys) return std::nullopt;
    if (keys->empty()) r.error("expected at least one keyframe", "/keyframes");
    for (std::size_t i = 0; i < keys->size(); ++i) {
        const auto& k = (*keys)[i];
        std::string ptr = fmt::format("/keyframes/{}", i);
        if (!r.is_object(k, ptr)) continue;
        r.unknown_keys(k, ptr, {"time", "position", "target", "up", "orientation", "world_scale", "ease", "params"},
                       "keyframe field");
        CameraKey key;
        key.world_scale = default_world_scale;
        r.required(k, "time", ptr, key.time);
        if (!path.keys_.empty() && key.time <= path.keys_.back().time)
            r.error(fmt::format("times must increase: {} follows {}", key.time, path.keys_.back().time), ptr + "/time");
        bool position_ok = r.required(k, "position", ptr, key.position);
        bool has_target = k.contains("target"), has_quat = k.contains("orientation");
        if (has_target == has_quat) r.error("give either a target [x, y, z] or an orientation [w, x, y, z]", ptr);
        if (glm::dvec3 t; has_target && r.required(k, "target", ptr, t)) {
            if (position_ok && glm::length(t - key.position) < 1e-12) r.error("the target is at the position", ptr + "/target");
            key.target = t;
        }
        if (has_target && r.optional(k, "up", ptr, key.up) && glm::length(key.up) < 1e-12)
            r.error("up must not be zero", ptr + "/up");
        if (has_quat) {
            std::array<double, 4> wxyz{};
            if (r.read_numbers(k["orientation"], ptr + "/orientation", wxyz)) {
                glm::dquat quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
                if (glm::length(quat) < 1e-9) r.error("expected a non-zero quaternion [w, x, y, z]", ptr + "/orientation");
                else key.orientation = glm::normalize(quat);
            }
        }
        r.optional(k, "world_scale", ptr, key.world_scale, NumberRange::positive());
        std::string ease;
        if (r.optional(k, "ease", ptr, ease, Choices{"linear", "in", "out", "in-out"}))
            key.ease = ease == "in" ? Ease::In : ease == "out" ? Ease::Out : ease == "in-out" ? Ease::InOut : Ease::Linear;
        if (key.target) key.orientation = look_at(key.position, *key.target, key.up).orientation;
        read_param_keys(r, k, ptr, key);
        path.keys_.push_back(key);
    }
    if (r.errors() > 0) return std::nullopt;
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
    // A last key written with a few decimals (10/3 s as 3.3333333) lands a hair before the frame
    // it means: a frame within a thousandth of a frame interval of the last key is the last frame.
    double duration = keys_.back().time - keys_.front().time;
    return static_cast<int>(std::floor(duration * fps_ + 1e-3)) + 1;
}

CameraSample CameraPath::sample(int frame) const { return at(keys_.front().time + frame / fps_); }

// A parameter's value at `time`: its own track through the keys that name it, with the same
// interpolation as the positions and the easing of the key each segment starts at.
std::vector<double> CameraPath::param_at(const std::string& name, double time) const {
    std::vector<const CameraKey*> track;
    for (const auto& k : keys_)
        if (k.params.count(name)) track.push_back(&k);
    auto value = [&](std::size_t i) -> const std::vector<double>& { return track[i]->params.at(name); };
    if (track.size() == 1 || time <= track.front()->time) return value(0);
    if (time >= track.back()->time) return value(track.size() - 1);
    std::size_t i = 0;
    while (time >= track[i + 1]->time) ++i;
    double s = eased(track[i]->ease, (time - track[i]->time) / (track[i + 1]->time - track[i]->time));
    const auto &a = value(i), &b = value(i + 1);
    const auto &before = i > 0 ? value(i - 1) : a, &after = i + 2 < track.size() ? value(i + 2) : b;
    std::vector<double> out(a.size());
    for (std::size_t c = 0; c < out.size(); ++c) {
        // Keys of another size are refused by check_path_params; here they only must not crash.
        double p1 = a[c], p2 = c < b.size() ? b[c] : a[c];
        double p0 = c < before.size() ? before[c] : p1, p3 = c < after.size() ? after[c] : p2;
        out[c] = smooth_ ? catmull_rom(p0, p1, p2, p3, s) : glm::mix(p1, p2, s);
    }
    return out;
}

CameraSample CameraPath::at(double time) const {
    CameraSample out;
    out.time = time;
    for (const auto& k : keys_)
        for (const auto& [name, _] : k.params)
            if (!out.params.count(name)) out.params[name] = param_at(name, time);
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
