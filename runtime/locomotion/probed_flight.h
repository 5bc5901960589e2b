#pragma once
// One frame of flight as the backends use it: read whatever probe answers have arrived (without
// waiting), move the head with Locomotion, and ask the probe about the new head and where it is
// heading. The answers come back a frame or two later.
#include <memory>
#include <utility>
#include <vector>

#include "locomotion/collision_probe.h"
#include "locomotion/locomotion.h"

namespace fg {

class ProbedFlight {
public:
    ProbedFlight(const vk::Context& ctx, const Pack& pack, const LocomotionSettings& settings, double world_scale);

    // Returns the new head position (scene units). `tracked_velocity`: how fast the tracked head
    // itself moves (scene units per second); the look-ahead probe adds it to the flight's, so a
    // head walking into the surface is answered for by the time it gets there.
    glm::dvec3 update(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt,
                      const glm::dvec3& tracked_velocity = glm::dvec3(0.0));

    const Locomotion& locomotion() const { return locomotion_; }
    void set_world_scale(double world_scale) { locomotion_.set_world_scale(world_scale); }
    // Coordinates moved by `delta` (a looping scene wrapped the head by whole periods): answers
    // held and answers still in flight move with them, so they stay true in the new cell.
    void translate(const glm::dvec3& delta);
    std::uint64_t answers() const { return answers_; }

private:
    CollisionProbe probe_;
    Locomotion locomotion_;
    std::uint64_t answers_ = 0;
    std::uint64_t last_ticket_ = 0;
    std::vector<std::pair<std::uint64_t, glm::dvec3>> pending_;   // (probes up to this ticket, move)
};

}  // namespace fg
