#include "locomotion/comfort_vignette.h"

#include <algorithm>
#include <cmath>

namespace fg {

double comfort_vignette(double speed, double turn, double max_strength, const ComfortVignetteSettings& s) {
    if (!(max_strength > 0.0)) return 0.0;
    double drive = std::abs(speed) / s.full_at_speed + std::abs(turn) / s.full_at_turn;
    return max_strength * std::clamp(std::isfinite(drive) ? drive : 1.0, 0.0, 1.0);
}

}  // namespace fg
