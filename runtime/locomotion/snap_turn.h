#pragma once
// 90° snap turns with a fade: a smooth artificial turn is the strongest cause of sim sickness, so
// the view fades to black, the play space turns about the head in one step while nothing is
// visible, and the view fades back in. The stick is edge-triggered: a turn needs the stick pushed
// past `press` and then let back inside `release` (the dead zone) before the next one.
namespace fg {

struct SnapTurnSettings {
    double angle_deg = 90.0;
    double fade_out_s = 0.1;    // to black
    double fade_in_s = 0.1;     // back from black
    double press = 0.7;         // |stick x| that starts a turn
    double release = 0.3;       // |stick x| under which the stick is re-armed (dead zone)
};

struct SnapTurnFrame {
    double brightness = 1.0;    // multiplies the image: 1 normal, 0 black
    double yaw_rad = 0.0;       // turn to apply to the play space this frame (about +y, at the head)
};

class SnapTurn {
public:
    explicit SnapTurn(const SnapTurnSettings& settings = {});

    // `stick_x` in [-1, 1]: positive turns right. `dt` in seconds. The yaw comes exactly once per
    // turn, on the frame the fade reaches black.
    SnapTurnFrame update(double stick_x, double dt);
    bool turning() const { return phase_ != Phase::Idle; }
    int turns() const { return turns_; }

private:
    enum class Phase { Idle, FadingOut, FadingIn };
    SnapTurnSettings settings_;
    Phase phase_ = Phase::Idle;
    double elapsed_ = 0.0;
    double pending_rad_ = 0.0;
    bool armed_ = true;
    int turns_ = 0;
};

}  // namespace fg
