#include "locomotion/snap_turn.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fg {

SnapTurn::SnapTurn(const SnapTurnSettings& settings) : settings_(settings) {}

SnapTurnFrame SnapTurn::update(double stick_x, double dt) {
    if (!std::isfinite(stick_x)) stick_x = 0.0;
    if (!(dt > 0.0)) dt = 0.0;
    SnapTurnFrame out;
    if (std::abs(stick_x) < settings_.release) armed_ = true;
    if (phase_ == Phase::Idle && armed_ && std::abs(stick_x) >= settings_.press) {
        armed_ = false;
        phase_ = Phase::FadingOut;
        elapsed_ = 0.0;
        // Stick right turns the view right: a negative rotation about +y (-z forward, +x right).
        pending_rad_ = (stick_x > 0.0 ? -1.0 : 1.0) * settings_.angle_deg * std::numbers::pi / 180.0;
        return {1.0, 0.0};   // the press frame still shows the full image; the fade starts next
    }
    if (phase_ == Phase::FadingOut) {
        elapsed_ += dt;
        out.brightness = std::clamp(1.0 - elapsed_ / std::max(settings_.fade_out_s, 1e-6), 0.0, 1.0);
        // Frame times summed in floating point land a hair short of the fade's end.
        if (out.brightness <= 1e-6) {
            out.brightness = 0.0;
            out.yaw_rad = pending_rad_;
            ++turns_;
            phase_ = Phase::FadingIn;
            elapsed_ = 0.0;
        }
    } else if (phase_ == Phase::FadingIn) {
        elapsed_ += dt;
        out.brightness = std::clamp(elapsed_ / std::max(settings_.fade_in_s, 1e-6), 0.0, 1.0);
        if (out.brightness >= 1.0 - 1e-6) {
            out.brightness = 1.0;
            phase_ = Phase::Idle;
        }
    }
    return out;
}

}  // namespace fg
