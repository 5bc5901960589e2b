#pragma once
// The desktop preview's camera: mouse-look (yaw and pitch, no roll) and flight along the view.
#include "frame/stereo_rig.h"

namespace fg::desktop {

class FlyCamera {
public:
    explicit FlyCamera(const HeadPose& start);

    // Mouse movement in pixels; `radians_per_pixel` sets the sensitivity.
    void look(double dx, double dy, double radians_per_pixel = 0.003);
    // Moves by `distance` scene units along the view (forward, right, up are -1, 0 or 1).
    void fly(double forward, double right, double up, double distance);

    HeadPose pose() const;
    void set_position(const glm::dvec3& p) { position_ = p; }
    // A snap turn: yaw about the camera itself (positive turns left, as about +y).
    void turn(double yaw_rad) { yaw_ += yaw_rad; }
    glm::dvec3 forward() const;

private:
    glm::dvec3 position_;
    double yaw_ = 0.0, pitch_ = 0.0;
};

}  // namespace fg::desktop
