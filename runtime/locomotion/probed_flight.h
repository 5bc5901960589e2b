#pragma once
// One frame of flight as the backends use it: read whatever probe answers have arrived (without
// waiting), move the head with Locomotion, and ask the probe about the new head and where it is
// heading. The answers come back a frame or two later.
#include <memory>

#include "locomotion/collision_probe.h"
#include "locomotion/locomotion.h"

namespace fg {

class ProbedFlight {
public:
    ProbedFlight(const vk::Context& ctx, const Pack& pack, const LocomotionSettings& settings, double world_scale);

    // Returns the new head position (scene units).
    glm::dvec3 update(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt);

    const Locomotion& locomotion() const { return locomotion_; }
    std::uint64_t answers() const { return answers_; }

private:
    CollisionProbe probe_;
    Locomotion locomotion_;
    std::uint64_t answers_ = 0;
};

}  // namespace fg
