#pragma once
// The display's refresh period, learned from the periods an OpenXR runtime predicts when it does
// not say its refresh rate. A runtime may answer placeholders before the display runs (Monado's
// first xrWaitFrame says 16 ms on any display) and stretches the period of a slow application to
// whole display periods that cover its frames (50, 100, 150 ms on a 50 ms display). So the first
// prediction is left out, and the period is the largest one that every later prediction is a whole
// multiple of: the display's, once the predictions are steady or vary.
#include <optional>

namespace fg {

class DisplayPeriod {
public:
    // One frame's predicted display period, in milliseconds, in the order the frames came.
    void observe(double predicted_ms);
    // The period learned so far; none before the first prediction after the placeholder.
    std::optional<double> ms() const { return period_ms_ ? std::optional<double>(period_ms_) : std::nullopt; }

private:
    int seen_ = 0;
    double period_ms_ = 0.0;
};

// No display refreshes faster than 10 kHz: the learned period never falls below this.
inline constexpr double kShortestDisplayPeriodMs = 0.1;

// The largest d of which a and b are both whole multiples, to within `tolerance` of d (relative).
double approximate_common_divisor(double a, double b, double tolerance);

}  // namespace fg
