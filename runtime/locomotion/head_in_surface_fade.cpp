#include "locomotion/head_in_surface_fade.h"

#include <algorithm>
#include <limits>

namespace fg {

double head_in_surface_brightness(const std::vector<ProbeSample>& probes, const glm::dvec3& head, double head_radius) {
    if (probes.empty() || !(head_radius > 0.0)) return 1.0;
    double at_least = -std::numeric_limits<double>::infinity();
    for (const auto& s : probes) at_least = std::max(at_least, s.distance - glm::length(head - s.point));
    return std::clamp(at_least / (0.5 * head_radius), 0.0, 1.0);
}

}  // namespace fg
