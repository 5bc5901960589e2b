#pragma once
// Tracked head motion cannot be stopped: flight stops a head radius from the surface, but a player
// who leans or walks into the fractal would see its inside (noise, or a march that starts past
// the surface). The view fades to black instead, as room-scale games do at walls. The probes
// answer a frame or two late, so the fade trusts only what they guarantee: a probe at q with
// estimate d says the distance at p is at least d - |p - q| (distance fields change no faster
// than 1); the head is dimmed unless some answer guarantees it clear. The look-ahead probe (placed
// along the head's velocity) keeps that bound tight while the head moves.
#include <vector>

#include <glm/glm.hpp>

#include "locomotion/collision_probe.h"

namespace fg {

// Brightness in [0, 1]: 1 while the probes guarantee the head at least half the head radius
// (scene units) from the surface, falling linearly to 0 where they guarantee nothing; 1 before
// the first answer.
double head_in_surface_brightness(const std::vector<ProbeSample>& probes, const glm::dvec3& head, double head_radius);

}  // namespace fg
