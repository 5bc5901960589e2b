#include "locomotion/world_scale.h"

#include <algorithm>
#include <cmath>

namespace fg {

double float_floor_scale(const glm::dvec3& head, double ipd_m, double spacings) {
    double biggest = std::max({std::abs(head.x), std::abs(head.y), std::abs(head.z)});
    if (!std::isfinite(biggest)) return 0.0;
    float f = static_cast<float>(biggest);
    double spacing = static_cast<double>(std::nextafter(f, INFINITY) - f);
    return ipd_m > 0.0 ? spacings * spacing / ipd_m : 0.0;
}

WorldScale::WorldScale(double initial, const WorldScaleSettings& settings)
    : settings_(settings), initial_(initial > 0.0 && std::isfinite(initial) ? initial : 1.0), current_(initial_), target_(initial_) {}

double WorldScale::update(double stick, double dt, const glm::dvec3& head, double ipd_m, double head_radius_m, double clearance) {
    if (!std::isfinite(stick)) stick = 0.0;
    if (!(dt > 0.0) || !std::isfinite(dt)) return current_;
    stick = std::clamp(stick, -1.0, 1.0);
    if (std::abs(stick) > settings_.dead_zone) target_ *= std::exp(stick * settings_.rate_per_s * dt);

    limited_by_ = "";
    double lo = initial_ * settings_.min_factor, hi = initial_ * settings_.max_factor;
    double floor = float_floor_scale(head, ipd_m, settings_.float_spacings);
    if (floor > lo) lo = floor;
    // Growing is allowed only as far as the guaranteed empty ball holds the grown head; a scale
    // that is already there is kept (shrinking is always safe).
    double by_clearance = head_radius_m > 0.0 ? std::max(current_, clearance / head_radius_m) : hi;
    if (by_clearance < hi) {
        hi = by_clearance;
        if (target_ > hi) limited_by_ = "clearance";
    }
    if (target_ > hi && !*limited_by_) limited_by_ = "scene range";
    if (target_ < lo) limited_by_ = floor >= lo && floor > initial_ * settings_.min_factor ? "float floor" : "scene range";
    target_ = std::clamp(target_, lo, std::max(lo, hi));

    const double keep = std::exp(-dt / std::max(settings_.time_constant_s, 1e-6));
    if (current_ != target_) current_ = std::exp(std::log(target_) + (std::log(current_) - std::log(target_)) * keep);
    return current_;
}

}  // namespace fg
