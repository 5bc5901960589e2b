#include "frame/frame_governor.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace fg {

std::string GovernorLevel::describe() const {
    std::string s = name.empty() ? "" : fmt::format("\"{}\": ", name);
    if (stereo) s += fmt::format("{}, ", stereo_mode_name(*stereo));
    if (cone_levels) s += fmt::format("{} cone levels, ", *cone_levels);
    if (taa && *taa) s += taa_upscale.value_or(1.0) > 1.0 ? fmt::format("TAA upsampling from 1/{:g}, ", *taa_upscale) : "TAA, ";
    s += fmt::format("scale {:.2f}, foveation {}", render_scale, foveation > 0.0 ? fmt::format("{:.2f}", foveation) : foveation < 0.0 ? "as the scene says" : "off");
    for (const auto& [k, v] : knobs) s += fmt::format(", {} {}", k, v);
    return s;
}

std::vector<GovernorLevel> governor_ladder(const PackManifest& m) {
    struct Step {
        double scale, foveation, epsilon_factor, max_steps_factor;
    };
    // Cheapest last. Resolution and foveation first: their error stays out of the fovea.
    const Step steps[] = {{1.0, -1.0, 1.0, 1.0}, {1.0, 0.6, 1.0, 1.0}, {0.85, 0.6, 1.5, 1.0}, {0.7, 0.5, 2.0, 0.5}, {0.5, 0.4, 3.0, 0.375}};
    std::vector<GovernorLevel> ladder;
    for (const auto& st : steps) {
        GovernorLevel level;
        level.render_scale = st.scale;
        level.foveation = st.foveation;
        auto knob = [&](const char* name, double factor) {
            const auto* spec = m.find_spec(name);
            if (!spec || factor == 1.0) return;
            double v = spec->value * factor;
            if (spec->type == ValueType::Int) v = std::round(v);
            if (spec->min) v = std::max(v, *spec->min);
            if (spec->max) v = std::min(v, *spec->max);
            level.knobs[name] = v;
        };
        knob("epsilon", st.epsilon_factor);
        knob("max_steps", st.max_steps_factor);
        ladder.push_back(std::move(level));
    }
    return ladder;
}

FrameGovernor::FrameGovernor(std::vector<GovernorLevel> ladder, const GovernorSettings& settings)
    : ladder_(std::move(ladder)), settings_(settings), resolution_(settings.resolution), recent_(settings.window) {
    if (ladder_.empty()) ladder_.push_back({});
    climb_wait_.assign(ladder_.size(), settings_.up_after);
}

GovernorLevel FrameGovernor::effective(int level, int steps) const {
    GovernorLevel l = ladder_.at(static_cast<std::size_t>(level));
    l.render_scale *= resolution_.scale_at(steps);
    return l;
}

bool FrameGovernor::observe(double gpu_ms, double budget_ms) {
    message_.clear();
    ++frames_at_level_;
    if (settings_.dynamic_resolution) {
        if (resolution_.observe(gpu_ms, budget_ms)) {
            message_ = "dynamic resolution, " + resolution_.message();
            return true;
        }
        // While the scale can still move, the ladder waits and judges nothing.
        if (!resolution_.pinned()) return false;
    }
    return observe_level(gpu_ms, budget_ms);
}

bool FrameGovernor::observe_level(double gpu_ms, double budget_ms) {
    if (cooldown_ > 0) {
        --cooldown_;
        return false;
    }
    recent_.push(gpu_ms);
    if (!recent_.full() || budget_ms <= 0.0) return false;
    const double mean = recent_.median();
    over_ = mean > budget_ms ? over_ + 1 : 0;
    under_ = mean < settings_.up_fraction * budget_ms ? under_ + 1 : 0;
    int next = level_;
    if (over_ >= settings_.down_after && !at_floor()) next = level_ + 1;
    else if (level_ > 0 && under_ >= climb_wait_[static_cast<std::size_t>(level_ - 1)]) next = level_ - 1;
    if (next == level_) {
        if (at_floor() && over_ >= settings_.down_after && !floor_reported_) {
            floor_reported_ = true;
            message_ = fmt::format("at the floor (level {}: {}), still {:.1f} ms of GPU time per frame for a {:.3g} ms budget",
                                   level_, effective().describe(), mean, budget_ms);
        }
        return false;
    }
    const char* why = next > level_ ? "over" : "well under";
    std::string backoff;
    if (next > level_ && climbed_ && frames_at_level_ < settings_.failed_climb_frames) {
        int& wait = climb_wait_[static_cast<std::size_t>(level_)];
        wait = std::min(2 * wait, settings_.most_up_after);
        backoff = fmt::format("; it fell back from level {} after {} frames, so climbing there again waits for {} judgements",
                              level_, frames_at_level_, wait);
    }
    climbed_ = next < level_;
    frames_at_level_ = 0;
    level_ = next;
    if (!at_floor()) floor_reported_ = false;
    over_ = under_ = 0;
    recent_.clear();
    cooldown_ = settings_.cooldown;
    resolution_.restart();
    message_ = fmt::format("level {} ({}): {:.1f} ms of GPU time per frame, {} the {:.3g} ms budget{}", level_,
                           effective().describe(), mean, why, budget_ms, backoff);
    return true;
}

FrameSettings settings_at_level(const FrameSettings& full, const GovernorLevel& level, std::uint32_t width,
                                std::uint32_t height) {
    FrameSettings f = full;
    f.taa = level.taa.value_or(full.taa);
    f.foveation = level.foveation;
    f.stereo = level.stereo.value_or(full.stereo);
    f.cone_levels = level.cone_levels.value_or(full.cone_levels);
    if (f.taa) {
        // Every level resolves to width x height and marches less by upsampling more: the history
        // stays at one size, so a level change carries it over unresampled (FrameExecutor::
        // take_history) and the first frame of a level keeps the picture converged so far.
        f.width = width;
        f.height = height;
        set_taa_upscale(f, level.taa_upscale.value_or(full.taa_upscale_factor) / level.render_scale);
    } else {
        f.width = std::max(8u, static_cast<std::uint32_t>(std::lround(width * level.render_scale)));
        f.height = std::max(8u, static_cast<std::uint32_t>(std::lround(height * level.render_scale)));
        // The display's pixels set the detail at any render scale: a lower level shows the same fractal.
        f.detail_scale = full.detail_scale * static_cast<double>(f.width) / width;
        set_taa_upscale(f, 1.0);
    }
    for (const auto& [k, v] : level.knobs) f.knobs[k] = v;
    return f;
}

}  // namespace fg
