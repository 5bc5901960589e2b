#include "locomotion/probed_flight.h"

namespace fg {

ProbedFlight::ProbedFlight(const vk::Context& ctx, const Pack& pack, const LocomotionSettings& settings, double world_scale)
    : probe_(ctx, pack), locomotion_(settings, world_scale) {}

glm::dvec3 ProbedFlight::update(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt) {
    if (auto answer = probe_.poll()) {
        locomotion_.on_probe(*answer);
        ++answers_;
    }
    glm::dvec3 next = locomotion_.step(head, direction, throttle, dt);
    probe_.submit(locomotion_.probe_points(next, locomotion_.velocity()));
    return next;
}

}  // namespace fg
