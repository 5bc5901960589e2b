#include "display_period.h"

#include <algorithm>
#include <cmath>

namespace fg {

double approximate_common_divisor(double a, double b, double tolerance) {
    if (a < b) std::swap(a, b);
    // Euclid's algorithm; a remainder within `tolerance` of the divisor (relative) counts as none.
    while (b > kShortestDisplayPeriodMs) {
        double r = std::fmod(a, b);
        if (r < tolerance * b || b - r < tolerance * b) r = 0.0;
        a = b;
        b = r;
    }
    return std::max(a, kShortestDisplayPeriodMs);
}

void DisplayPeriod::observe(double predicted_ms) {
    if (!(predicted_ms > 0.0) || ++seen_ == 1) return;  // the first prediction may be a placeholder
    // Clock jitter of 2 % of a period counts as exact.
    period_ms_ = period_ms_ == 0.0 ? predicted_ms : approximate_common_divisor(period_ms_, predicted_ms, 0.02);
}

}  // namespace fg
