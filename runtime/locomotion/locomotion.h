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
#include <nlohmann/json.hpp>

#include "locomotion/collision_probe.h"

namespace fg {

struct LocomotionSettings {
    double speed_per_distance = 1.0;   // 1/s: speed = this * distance to the nearest surface
    double max_speed = 2.0;            // scene units per second per unit of world scale
    // Metres (scene units per unit of world scale): the closest the head gets. More than half the
    // distance between the eyes, so that neither eye enters the surface.
    double head_radius = 0.05;
    double latency_s = 0.05;           // how far ahead the second probe looks along the velocity
};

// From the graph's scene.locomotion: speed_per_distance, max_speed, head_radius (all optional).
LocomotionSettings locomotion_settings(const nlohmann::json& scene_locomotion);

class Locomotion {
public:
    Locomotion(const LocomotionSettings& settings, double world_scale);

    // Where to probe now: the head, and where the head will be after `latency_s` at `velocity`.
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
    std::vector<ProbeSample> samples_;   // the empty balls (d > 0) that bound each step
    std::vector<ProbeSample> answers_;
    glm::dvec3 velocity_{0.0};
};

}  // namespace fg
