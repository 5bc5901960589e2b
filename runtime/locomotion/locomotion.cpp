#include "locomotion/locomotion.h"

#include <algorithm>
#include <cmath>

namespace fg {

Locomotion::Locomotion(const LocomotionSettings& settings, double world_scale, double probe_latency_s)
    : settings_(settings), world_scale_(world_scale), probe_latency_s_(probe_latency_s) {}

std::vector<glm::dvec3> Locomotion::probe_points(const glm::dvec3& head, const glm::dvec3& velocity) const {
    return {head, head + velocity * probe_latency_s_};
}

void Locomotion::on_probe(const ProbeResult& result) {
    samples_.clear();
    answers_.clear();
    for (const auto& s : result.samples) {
        if (!std::isfinite(s.distance)) continue;
        answers_.push_back(s);
        if (s.distance > 0.0) samples_.push_back(s);
    }
}

double Locomotion::guaranteed_clearance(const glm::dvec3& p) const {
    double best = 0.0;
    for (const auto& s : samples_) best = std::max(best, s.distance - glm::length(p - s.point));
    return best;
}

glm::dvec3 Locomotion::step(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt) {
    velocity_ = glm::dvec3(0.0);
    const double margin = settings_.head_radius * world_scale_;
    const double clearance = guaranteed_clearance(head);
    if (clearance <= margin || glm::length(direction) < 1e-12 || throttle <= 0.0 || dt <= 0.0) return head;
    const glm::dvec3 dir = glm::normalize(direction);
    double speed = std::min(settings_.speed_per_distance * clearance, settings_.max_speed * world_scale_) * throttle;
    double want = speed * dt;
    // The farthest point along dir still inside some probe's empty ball, less the margin.
    double allowed = 0.0;
    for (const auto& s : samples_) {
        double r = s.distance - margin;
        glm::dvec3 oc = head - s.point;
        double c = glm::dot(oc, oc) - r * r;
        if (r <= 0.0 || c > 0.0) continue;   // the head is not inside this ball
        double b = glm::dot(oc, dir);
        double t = -b + std::sqrt(std::max(0.0, b * b - c));
        allowed = std::max(allowed, t);
    }
    double moved = std::clamp(want, 0.0, allowed);
    velocity_ = dir * (moved / dt);
    return head + dir * moved;
}

}  // namespace fg
