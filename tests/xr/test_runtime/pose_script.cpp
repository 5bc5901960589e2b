#include "pose_script.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace fgxrt {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

XrQuaternionf yaw_pitch(double yaw, double pitch) {
    // Yaw about +y, then pitch about the head's +x (OpenXR: -z forward, +y up).
    double cy = std::cos(yaw * 0.5), sy = std::sin(yaw * 0.5), cp = std::cos(pitch * 0.5), sp = std::sin(pitch * 0.5);
    XrQuaternionf q;
    q.w = static_cast<float>(cy * cp);
    q.x = static_cast<float>(cy * sp);
    q.y = static_cast<float>(sy * cp);
    q.z = static_cast<float>(-sy * sp);
    return q;
}

}  // namespace

PoseScript::PoseScript() {
    const char* path = std::getenv("FG_XR_TEST_POSES");
    if (path && *path) {
        try {
            std::ifstream in(path);
            if (!in) throw std::runtime_error("cannot open it");
            auto j = nlohmann::json::parse(in);
            ipd_ = j.value("ipd", 0.064);
            for (const auto& k : j.at("keys")) {
                PoseKey key;
                key.t = k.at("t").get<double>();
                for (int i = 0; i < 3; ++i) key.position[i] = k.at("position").at(i).get<double>();
                key.yaw_deg = k.value("yaw_deg", 0.0);
                key.pitch_deg = k.value("pitch_deg", 0.0);
                keys_.push_back(key);
            }
        } catch (const std::exception& e) {
            error_ = std::string("FG_XR_TEST_POSES ") + path + ": " + e.what();
            keys_.clear();
        }
    }
    if (keys_.empty()) {
        // A step forward while looking left, then right.
        keys_ = {{0.0, {0.0, 0.0, 0.0}, 0.0, 0.0}, {0.5, {0.0, 0.0, -0.1}, 12.0, 4.0}, {1.0, {0.02, 0.0, -0.2}, -12.0, -4.0}};
    }
}

XrPosef PoseScript::head(double t) const {
    const PoseKey* a = &keys_.front();
    const PoseKey* b = a;
    for (std::size_t i = 0; i + 1 < keys_.size(); ++i) {
        if (t >= keys_[i].t) {
            a = &keys_[i];
            b = &keys_[i + 1];
        }
    }
    double span = b->t - a->t;
    double f = span > 0.0 ? std::clamp((t - a->t) / span, 0.0, 1.0) : 1.0;
    if (t >= keys_.back().t) a = b = &keys_.back();
    XrPosef pose;
    pose.position = {static_cast<float>(a->position[0] + f * (b->position[0] - a->position[0])),
                     static_cast<float>(a->position[1] + f * (b->position[1] - a->position[1])),
                     static_cast<float>(a->position[2] + f * (b->position[2] - a->position[2]))};
    pose.orientation = yaw_pitch((a->yaw_deg + f * (b->yaw_deg - a->yaw_deg)) * kDeg,
                                 (a->pitch_deg + f * (b->pitch_deg - a->pitch_deg)) * kDeg);
    return pose;
}

XrPosef PoseScript::eye(double t, int eye) const {
    XrPosef h = head(t);
    // The head's +x axis, rotated by its orientation.
    const XrQuaternionf& q = h.orientation;
    double rx = 1.0 - 2.0 * (q.y * q.y + q.z * q.z), ry = 2.0 * (q.x * q.y + q.w * q.z), rz = 2.0 * (q.x * q.z - q.w * q.y);
    double side = (eye == 0 ? -0.5 : 0.5) * ipd_;
    h.position.x += static_cast<float>(rx * side);
    h.position.y += static_cast<float>(ry * side);
    h.position.z += static_cast<float>(rz * side);
    return h;
}

XrFovf PoseScript::fov(int eye) const {
    // Wider towards the temple, like a headset's lenses.
    float inner = static_cast<float>(-44.0 * kDeg), outer = static_cast<float>(50.0 * kDeg);
    XrFovf f;
    f.angleLeft = eye == 0 ? -outer : inner;
    f.angleRight = eye == 0 ? -inner : outer;
    f.angleDown = static_cast<float>(-48.0 * kDeg);
    f.angleUp = static_cast<float>(45.0 * kDeg);
    return f;
}

XrDuration EventScript::period_ns(int frame) const {
    for (const auto& [ms, frames] : periods) {
        if (frames <= 0 || frame < frames) return static_cast<XrDuration>(ms * 1e6);
        frame -= frames;
    }
    return 11'111'111;
}

EventScript::EventScript() {
    if (const char* p = std::getenv("FG_XR_TEST_PERIODS")) {
        std::stringstream in(p);
        std::string item;
        while (std::getline(in, item, ',')) {
            double ms = std::atof(item.c_str());
            auto colon = item.find(':');
            int frames = colon == std::string::npos ? 0 : std::atoi(item.c_str() + colon + 1);
            if (ms > 0.0) periods.emplace_back(ms, frames);
        }
    }
    const char* s = std::getenv("FG_XR_TEST_EVENTS");
    if (!s) return;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        auto at = item.find('@');
        if (at == std::string::npos) continue;
        int frame = std::atoi(item.c_str() + at + 1);
        std::string what = item.substr(0, at);
        if (what == "stop") stop_at = frame;
        if (what == "loss") loss_at = frame;
    }
}

}  // namespace fgxrt
