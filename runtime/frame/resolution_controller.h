#pragma once
// Dynamic resolution: the render scale as a continuous control of the frame's GPU time, in small
// steps, before any knob of the governor's ladder moves (Vlachos, "Advanced VR Rendering
// Performance", GDC 2016). The time is steered into a band below the budget: over it, the scale
// drops at once to where the time would fit (dropped frames are the worst outcome); under it, the
// scale climbs one step at a time, or at once when the time is far below the band. Inside the band
// nothing changes, so a steady scene settles. GPU time is taken to grow with the marched pixels,
// the square of the scale; what does not (a pass at the output size) only makes a step smaller
// than predicted, and the next judgement takes another. A climb that falls straight back holds the
// scale below it for a while, longer each time: the cost need not be smooth in the scale.
#include <string>

#include "frame/median_window.h"

namespace fg {

struct ResolutionSettings {
    double lowest = 0.65;   // the smallest scale, of each axis (0.42 of the pixels)
    double step = 0.05;     // scales are whole steps: each has its own frame graph, built once
    double aim = 0.8;       // the time steered to, of the budget
    double band = 0.1;      // no change while the time is within aim +- band (of the budget)
    int window = 5;         // frames whose median is judged
    int climb_after = 3;    // judgements in a row under the band before a climb
    int settle = 2;         // frames after a change left unjudged (the new size's first times)
    // A climb that falls back within this many frames keeps the scale below the one it reached for
    // `first_hold` frames, twice as long at each repeat, up to `longest_hold`.
    int failed_climb_frames = 60;
    int first_hold = 60;
    int longest_hold = 3840;
};

class ResolutionController {
public:
    explicit ResolutionController(const ResolutionSettings& settings = {});

    // One frame's GPU time and budget; true when the scale changed (it applies from the next frame).
    bool observe(double gpu_ms, double budget_ms);

    double scale() const { return scale_at(steps_); }
    double scale_at(int steps) const { return 1.0 - settings_.step * steps; }
    // The scale in whole steps below 1 (0: full resolution): a key for the frame graph it needs.
    int steps() const { return steps_; }
    int most_steps() const { return most_steps_; }
    // The scale can go no further the way the last judged time asks: the governor's ladder may move.
    // It holds until a judgement says otherwise (not while a new level's first times settle).
    bool pinned() const { return pinned_; }
    // The ladder moved: the times judged so far are another setting's.
    void restart();
    // Why the last change happened (for the log).
    const std::string& message() const { return message_; }

private:
    ResolutionSettings settings_;
    int steps_ = 0, most_steps_ = 0, settle_ = 0;
    int frames_ = 0, over_ = 0, under_ = 0;
    int climbed_to_ = -1, climbed_at_ = 0;   // the last climb: its steps and frame
    int ceiling_ = 0, ceiling_until_ = 0;    // a climb stops at `ceiling_` steps until that frame
    int hold_ = 0;                           // frames the next failed climb holds the ceiling
    bool pinned_ = false;
    MedianWindow recent_;
    std::string message_;
};

}  // namespace fg
