#include "desktop/fly_camera.h"

#include <algorithm>
#include <cmath>

namespace fg::desktop {

FlyCamera::FlyCamera(const HeadPose& start) : position_(start.position) {
    glm::dvec3 f = glm::mat3_cast(start.orientation) * glm::dvec3(0.0, 0.0, -1.0);
    yaw_ = std::atan2(-f.x, -f.z);
    pitch_ = std::asin(std::clamp(f.y, -1.0, 1.0));
}

void FlyCamera::look(double dx, double dy, double radians_per_pixel) {
    yaw_ -= dx * radians_per_pixel;
    // Just short of straight up or down, where yaw would spin.
    pitch_ = std::clamp(pitch_ - dy * radians_per_pixel, -1.55, 1.55);
}

HeadPose FlyCamera::pose() const {
    HeadPose p;
    p.position = position_;
    p.orientation = glm::angleAxis(yaw_, glm::dvec3(0.0, 1.0, 0.0)) * glm::angleAxis(pitch_, glm::dvec3(1.0, 0.0, 0.0));
    return p;
}

glm::dvec3 FlyCamera::forward() const { return glm::mat3_cast(pose().orientation) * glm::dvec3(0.0, 0.0, -1.0); }

void FlyCamera::fly(double forward, double right, double up, double distance) {
    glm::dmat3 basis = glm::mat3_cast(pose().orientation);
    glm::dvec3 dir = forward * -basis[2] + right * basis[0] + up * glm::dvec3(0.0, 1.0, 0.0);
    if (glm::length(dir) < 1e-12) return;
    position_ += glm::normalize(dir) * distance;
}

}  // namespace fg::desktop
