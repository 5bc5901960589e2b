#include "frame/resolution_controller.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace fg {

ResolutionController::ResolutionController(const ResolutionSettings& settings)
    : settings_(settings), most_steps_(static_cast<int>(std::floor((1.0 - settings.lowest) / settings.step + 1e-9))),
      hold_(settings.first_hold), recent_(settings.window) {}

void ResolutionController::restart() {
    recent_.clear();
    settle_ = settings_.settle;
}

bool ResolutionController::observe(double gpu_ms, double budget_ms) {
    message_.clear();
    ++frames_;
    if (settle_ > 0) {
        --settle_;
        return false;
    }
    recent_.push(gpu_ms);
    if (!recent_.full() || budget_ms <= 0.0) return false;
    const double ms = recent_.median();
    const double aim = settings_.aim * budget_ms, high = (settings_.aim + settings_.band) * budget_ms,
                 low = (settings_.aim - settings_.band) * budget_ms;
    pinned_ = (ms > high && steps_ == most_steps_) || (ms < low && steps_ == 0);
    over_ = ms > high ? over_ + 1 : 0;
    under_ = ms < low ? under_ + 1 : 0;
    if (pinned_ || (ms >= low && ms <= high)) return false;
    // Frame times are noisy (lavapipe's by 20 % at a fixed setting): a time over the budget itself
    // drops the scale at once, one merely over the band waits for a second judgement, and a climb
    // for `climb_after`.
    if (ms > high && ms <= budget_ms && over_ < 2) return false;
    if (ms < low && under_ < settings_.climb_after) return false;
    // The scale whose time would be the aim, in whole steps: down to at least one step below, up by
    // one step, or to it where the time is under half the aim.
    const double fits = scale() * std::sqrt(aim / ms);
    const int fits_steps = std::clamp(static_cast<int>(std::ceil((1.0 - fits) / settings_.step - 1e-9)), 0, most_steps_);
    int next = steps_;
    std::string backoff;
    if (ms > high) {
        next = std::max(fits_steps, steps_ + 1);
        if (steps_ == climbed_to_ && frames_ - climbed_at_ < settings_.failed_climb_frames) {
            // A climb that did not fit: back to the step below, whose time fitted. The time is no
            // smooth function of the scale (a cliff between two steps), and climbing there again
            // waits twice as long each time.
            next = steps_ + 1;
            ceiling_ = steps_ + 1;
            ceiling_until_ = frames_ + hold_;
            backoff = fmt::format("; it fell back from {:.2f}, so climbing there again waits {} frames", scale(), hold_);
            hold_ = std::min(2 * hold_, settings_.longest_hold);
        }
    } else {
        next = ms < 0.5 * aim ? std::min(fits_steps, steps_ - 1) : steps_ - 1;
        if (frames_ < ceiling_until_) next = std::max(next, ceiling_);
    }
    next = std::clamp(next, 0, most_steps_);
    if (next == steps_) return false;
    message_ = fmt::format("scale {:.2f} -> {:.2f}: {:.1f} ms of GPU time per frame, {} {:.0f}-{:.0f} % of the {:.3g} ms budget{}",
                           scale(), scale_at(next), ms, ms > high ? "over" : "under",
                           100.0 * (settings_.aim - settings_.band), 100.0 * (settings_.aim + settings_.band), budget_ms, backoff);
    if (next < steps_) {
        climbed_to_ = next;
        climbed_at_ = frames_;
    }
    steps_ = next;
    over_ = under_ = 0;
    recent_.clear();
    settle_ = settings_.settle;
    return true;
}

}  // namespace fg
