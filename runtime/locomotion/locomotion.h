#pragma once
// Flight through a fractal without entering it. The head flies along a direction (gaze or a
// key) at a speed proportional to the world scale and to the distance to the nearest surface, so
// it slows down near detail and crosses empty space fast. Collisions use the asynchronous probe:
// a probe at point q with distance d says the ball of radius d around q is empty, however old
// the answer. A step is allowed only while the head stays inside such a ball, less a margin (the
// head's radius), so a late answer makes the flight stop short, never go through.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "graph/scene_settings.h"
#include "locomotion/collision_probe.h"

namespace fg {

// How late a probe's answer arrives, roughly: the look-ahead probe asks about where the head will
// be after this long. The runtime's, not the scene's (the scene's limits are LocomotionSettings).
inline constexpr double kProbeLatencyS = 0.05;

class Locomotion {
public:
    // `settings`: the scene's limits (scene.locomotion in the graph).
    Locomotion(const LocomotionSettings& settings, double world_scale, double probe_latency_s = kProbeLatencyS);

    // Where to probe now: the head, and where the head will be after the probe latency at `velocity`.
    std::vector<glm::dvec3> probe_points(const glm::dvec3& head, const glm::dvec3& velocity) const;
    // The newest answers; older ones are forgotten.
    void on_probe(const ProbeResult& result);

    // Moves the head along `direction` (unit length, or zero) at `throttle` times the
    // distance-proportional speed (a scroll wheel may push it above 1; the probes still bound the
    // step), for `dt` seconds; returns the new head position.
    glm::dvec3 step(const glm::dvec3& head, const glm::dvec3& direction, double throttle, double dt);

    // The distance to the nearest surface that the probes guarantee at `p` (0 when none does).
    double guaranteed_clearance(const glm::dvec3& p) const;
    const glm::dvec3& velocity() const { return velocity_; }
    bool has_probe() const { return !samples_.empty(); }
    // Every finite answer of the newest probe, the head inside the surface (d <= 0) included.
    const std::vector<ProbeSample>& answers() const { return answers_; }
    // Speed and head radius follow the world scale as it changes (world_scale.h).
    void set_world_scale(double world_scale) { world_scale_ = world_scale; }
    double head_radius_m() const { return settings_.head_radius; }
    // The scene moved by `delta` under the head (a looping scene wrapped): the answers move with it.
    void translate(const glm::dvec3& delta) {
        for (auto& s : samples_) s.point += delta;
        for (auto& s : answers_) s.point += delta;
    }

private:
    LocomotionSettings settings_;
    double world_scale_ = 1.0;
    double probe_latency_s_ = kProbeLatencyS;
    std::vector<ProbeSample> samples_;   // the empty balls (d > 0) that bound each step
    std::vector<ProbeSample> answers_;
    glm::dvec3 velocity_{0.0};
};

}  // namespace fg
