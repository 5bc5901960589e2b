#include "input_script.h"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fgxrt {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

HandInput read_hand(const nlohmann::json& j, HandInput h) {
    h.trigger = j.value("trigger", h.trigger);
    h.squeeze = j.value("squeeze", h.squeeze);
    if (j.contains("thumbstick")) {
        h.thumbstick[0] = j.at("thumbstick").at(0).get<double>();
        h.thumbstick[1] = j.at("thumbstick").at(1).get<double>();
    }
    if (j.contains("select")) h.select = j.at("select").get<bool>();
    if (j.contains("aim")) {
        const auto& a = j.at("aim");
        h.has_aim = true;
        for (int i = 0; i < 3; ++i) h.aim_position[i] = a.at("position").at(i).get<double>();
        h.aim_yaw_deg = a.value("yaw_deg", 0.0);
        h.aim_pitch_deg = a.value("pitch_deg", 0.0);
    }
    return h;
}

XrQuaternionf multiply(const XrQuaternionf& a, const XrQuaternionf& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

XrVector3f rotate(const XrQuaternionf& q, const XrVector3f& v) {
    XrQuaternionf p{v.x, v.y, v.z, 0.0f};
    XrQuaternionf c{-q.x, -q.y, -q.z, q.w};
    XrQuaternionf r = multiply(multiply(q, p), c);
    return {r.x, r.y, r.z};
}

}  // namespace

InputScript::InputScript() {
    const char* path = std::getenv("FG_XR_TEST_INPUT");
    if (!path || !*path) return;
    try {
        std::ifstream in(path);
        if (!in) throw std::runtime_error("cannot open it");
        auto j = nlohmann::json::parse(in);
        if (j.contains("profile")) profile_ = "/interaction_profiles/" + j.at("profile").get<std::string>();
        HandInput held[2];
        for (const auto& k : j.at("keys")) {
            InputKey key;
            key.t = k.at("t").get<double>();
            const char* names[2] = {"left", "right"};
            for (int h = 0; h < 2; ++h) {
                if (k.contains(names[h])) held[h] = read_hand(k.at(names[h]), held[h]);
                key.hands[h] = held[h];
            }
            keys_.push_back(key);
        }
    } catch (const std::exception& e) {
        error_ = std::string("FG_XR_TEST_INPUT ") + path + ": " + e.what();
        keys_.clear();
    }
}

const HandInput& InputScript::hand(int hand, double t) const {
    static const HandInput idle;
    const InputKey* at = nullptr;
    for (const auto& k : keys_)
        if (t >= k.t) at = &k;
    return at ? at->hands[hand] : idle;
}

ComponentValue InputScript::value(const std::string& component, double t) const {
    ComponentValue v;
    int h = component.rfind("/user/hand/left/", 0) == 0 ? 0 : component.rfind("/user/hand/right/", 0) == 0 ? 1 : -1;
    if (h < 0) return v;
    const HandInput& in = hand(h, t);
    const std::string c = component.substr(component.find("/input/") == std::string::npos ? component.size()
                                                                                           : component.find("/input/") + 7);
    auto flag = [&](bool b) { v.x = b ? 1.0f : 0.0f; };
    if (c == "trigger/value") v.x = static_cast<float>(in.trigger);
    else if (c == "trigger/click") flag(in.trigger >= 0.5);
    else if (c == "select/click") flag(in.select.value_or(in.trigger >= 0.5));
    else if (c == "squeeze/value") v.x = static_cast<float>(in.squeeze);
    else if (c == "squeeze/click") flag(in.squeeze >= 0.5);
    else if (c == "thumbstick") {
        v.x = static_cast<float>(in.thumbstick[0]);
        v.y = static_cast<float>(in.thumbstick[1]);
        v.is_vector = true;
    } else if (c == "thumbstick/x") v.x = static_cast<float>(in.thumbstick[0]);
    else if (c == "thumbstick/y") v.x = static_cast<float>(in.thumbstick[1]);
    return v;
}

XrPosef InputScript::aim(int hand_index, double t, const XrPosef& head) const {
    const HandInput& in = hand(hand_index, t);
    XrPosef pose;
    if (in.has_aim) {
        double cy = std::cos(in.aim_yaw_deg * kDeg * 0.5), sy = std::sin(in.aim_yaw_deg * kDeg * 0.5);
        double cp = std::cos(in.aim_pitch_deg * kDeg * 0.5), sp = std::sin(in.aim_pitch_deg * kDeg * 0.5);
        pose.orientation = {static_cast<float>(cy * sp), static_cast<float>(sy * cp), static_cast<float>(-sy * sp),
                            static_cast<float>(cy * cp)};
        pose.position = {static_cast<float>(in.aim_position[0]), static_cast<float>(in.aim_position[1]),
                         static_cast<float>(in.aim_position[2])};
        return pose;
    }
    XrVector3f offset = rotate(head.orientation, {hand_index == 0 ? -0.2f : 0.2f, -0.3f, -0.3f});
    pose.orientation = head.orientation;
    pose.position = {head.position.x + offset.x, head.position.y + offset.y, head.position.z + offset.z};
    return pose;
}

}  // namespace fgxrt
