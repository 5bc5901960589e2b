#include "locomotion/play_space.h"

#include <cmath>

namespace fg {

PlaySpace::PlaySpace(const HeadPose& origin, double world_scale)
    : position_(origin.position), orientation_(origin.orientation), scale_(world_scale) {}

glm::dvec3 PlaySpace::point(const glm::dvec3& tracked) const { return position_ + scale_ * (orientation_ * tracked); }

glm::dvec3 PlaySpace::direction(const glm::dvec3& tracked) const { return orientation_ * tracked; }

glm::dquat PlaySpace::orientation(const glm::dquat& tracked) const { return orientation_ * tracked; }

void PlaySpace::turn_about(const glm::dvec3& tracked_head, double yaw_rad) {
    const glm::dvec3 head = point(tracked_head);
    orientation_ = glm::normalize(orientation_ * glm::angleAxis(yaw_rad, glm::dvec3(0.0, 1.0, 0.0)));
    position_ = head - scale_ * (orientation_ * tracked_head);
}

void PlaySpace::rescale_about(const glm::dvec3& tracked_head, double world_scale) {
    const glm::dvec3 head = point(tracked_head);
    scale_ = world_scale;
    position_ = head - scale_ * (orientation_ * tracked_head);
}

glm::dvec3 periodic_cell_shift(const glm::dvec3& p, const glm::dvec3& period) {
    glm::dvec3 shift(0.0);
    for (int i = 0; i < 3; ++i)
        if (period[i] > 0.0 && std::isfinite(p[i])) shift[i] = period[i] * std::floor(p[i] / period[i] + 0.5);
    return shift;
}

glm::dvec3 PlaySpace::wrap(const glm::dvec3& tracked_head, const glm::dvec3& period) {
    const glm::dvec3 shift = periodic_cell_shift(point(tracked_head), period);
    position_ -= shift;
    return shift;
}

}  // namespace fg
