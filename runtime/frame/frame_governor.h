#pragma once
// Holding the frame rate: a headset shows a dropped frame as a judder, so the runtime keeps the
// GPU time of a frame inside the display period (or --budget-ms). The governor reads the GPU
// time of recent frames and moves along a ladder of settings, each cheaper and less accurate
// than the one before (render scale, foveation, then the epsilon and step-cap knobs), the
// trade-off `fgplay bench` measures. Hysteresis: it steps down only after several frames over
// budget, steps up only after many frames well under it, waits after each change, and waits
// twice as long to climb again to a level it just fell back from, so the image does not flicker
// between two settings.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frame/frame_settings.h"
#include "frame/resolution_controller.h"
#include "pack/manifest.h"

namespace fg {

struct GovernorLevel {
    double render_scale = 1.0;           // of the per-eye render size
    double foveation = -1.0;             // fovea radius in half image heights, 0 = off, < 0 = as the scene says
    std::map<std::string, double> knobs; // absolute knob values for this pack
    // Set by a measured ladder (trade_off_ladder.h): the benchmark's name for the setting, and its
    // stereo mode and conemarch levels; unset, the player's own are kept.
    std::string name;
    std::optional<StereoMode> stereo;
    std::optional<std::uint32_t> cone_levels;
    std::optional<bool> taa;             // temporal anti-aliasing, where the ladder says
    std::optional<double> taa_upscale;   // with it, temporal upsampling from 1/this of the render size
    std::string describe() const;
};

// The ladder for a pack: level 0 is the pack's own accuracy at full size; knobs the pack does
// not have are left out, and values stay inside each knob's range.
std::vector<GovernorLevel> governor_ladder(const PackManifest& manifest);

// The frame settings at `level`: `full` (full accuracy) at the level's render scale of `width` x
// `height`, with its foveation, and its stereo mode, cone levels, anti-aliasing and knobs where it
// sets them (else full's: its taa_upscale_factor is the player's own upsampling). With temporal
// anti-aliasing every level shows width x height: its render scale divides the upsampling factor.
FrameSettings settings_at_level(const FrameSettings& full, const GovernorLevel& level, std::uint32_t width,
                                std::uint32_t height);

struct GovernorSettings {
    int window = 3;          // frames whose median GPU time is judged
    int down_after = 2;      // consecutive averages over budget before stepping down
    int up_after = 6;        // consecutive averages under `up_fraction` of the budget before stepping up
    int cooldown = 3;        // frames ignored after a change (new pipelines, new sizes)
    double up_fraction = 0.6;
    // A climb that falls back within `failed_climb_frames` frames doubles the judgements the next
    // climb to that level waits for, up to `most_up_after`: two rungs that straddle the budget
    // settle on the cheaper one instead of switching every few frames.
    int failed_climb_frames = 60;
    int most_up_after = 768;
    // Dynamic resolution inside each level (resolution_controller.h): the level's render scale
    // times a scale steered in small steps; the ladder moves only when that scale is pinned at an
    // end of its range. Off, the ladder alone governs.
    bool dynamic_resolution = false;
    ResolutionSettings resolution;
};

class FrameGovernor {
public:
    FrameGovernor(std::vector<GovernorLevel> ladder, const GovernorSettings& settings = {});

    // One frame's GPU time and budget; true when the level or the dynamic scale changed.
    bool observe(double gpu_ms, double budget_ms);

    int level() const { return level_; }
    const GovernorLevel& current() const { return ladder_[static_cast<std::size_t>(level_)]; }
    // The current level with its render scale times the dynamic one: what to render now.
    GovernorLevel effective() const { return effective(level_, resolution_.steps()); }
    // Any level at any dynamic scale (steps of ResolutionController::steps()).
    GovernorLevel effective(int level, int steps) const;
    // The dynamic scales a level can take, in steps below 1: 0 without dynamic resolution.
    int most_scale_steps() const { return settings_.dynamic_resolution ? resolution_.most_steps() : 0; }
    // One number for each level and dynamic scale (the frame graph each needs).
    int setting_key(int level, int steps) const { return level * (most_scale_steps() + 1) + steps; }
    int setting_key() const { return setting_key(level_, resolution_.steps()); }
    const ResolutionController& resolution() const { return resolution_; }
    bool at_floor() const { return level_ + 1 == static_cast<int>(ladder_.size()); }
    int levels() const { return static_cast<int>(ladder_.size()); }
    const std::vector<GovernorLevel>& ladder() const { return ladder_; }
    // Why the last change happened, or that the floor cannot hold the budget (for the log).
    const std::string& message() const { return message_; }

private:
    bool observe_level(double gpu_ms, double budget_ms);

    std::vector<GovernorLevel> ladder_;
    GovernorSettings settings_;
    ResolutionController resolution_;
    int level_ = 0, over_ = 0, under_ = 0, cooldown_ = 0;
    int frames_at_level_ = 0;
    bool climbed_ = false;                // the current level was reached by a climb
    std::vector<int> climb_wait_;         // per level: judgements under the budget a climb to it waits for
    bool floor_reported_ = false;
    MedianWindow recent_;
    std::string message_;
};

}  // namespace fg
