#include "locomotion/probed_flight.h"

namespace fg {

ProbedFlight::ProbedFlight(const vk::Context& ctx, const Pack& pack, const LocomotionSettings& settings, double world_scale)
    : probe_(ctx, pack), locomotion_(settings, world_scale) {}

glm::dvec3 ProbedFlight::update(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt,
                                const glm::dvec3& tracked_velocity) {
    if (auto answer = probe_.poll()) {
        for (const auto& [upto, delta] : pending_)
            if (answer->ticket <= upto)
                for (auto& sample : answer->samples) sample.point += delta;
        std::erase_if(pending_, [&](const auto& p) { return p.first <= answer->ticket; });
        locomotion_.on_probe(*answer);
        ++answers_;
    }
    glm::dvec3 next = locomotion_.step(head, direction, throttle, dt);
    if (std::uint64_t ticket = probe_.submit(locomotion_.probe_points(next, locomotion_.velocity() + tracked_velocity))) last_ticket_ = ticket;
    return next;
}

void ProbedFlight::translate(const glm::dvec3& delta) {
    locomotion_.translate(delta);
    if (last_ticket_) pending_.emplace_back(last_ticket_, delta);
}

}  // namespace fg
