#include "frame/trade_off_ladder.h"

#include <cmath>

#include <fmt/format.h>

namespace fg {

std::vector<GovernorLevel> trade_off_ladder(const PackManifest& manifest, const std::vector<TradeOff>& front) {
    std::vector<GovernorLevel> ladder;
    for (auto it = front.rbegin(); it != front.rend(); ++it) {
        GovernorLevel level;
        level.name = it->setting;
        level.render_scale = it->render_scale;
        level.foveation = it->frame.foveation;
        level.stereo = it->frame.stereo;
        level.cone_levels = it->frame.cone_levels;
        level.taa = it->frame.taa;
        level.taa_upscale = it->taa_upscale;
        for (const auto& [k, v] : it->frame.knobs) {
            const auto* spec = manifest.find_spec(k);
            if (!spec)
                throw TradeOffError(fmt::format("setting \"{}\"", it->setting),
                                    fmt::format("'{}' is not a knob of the pack '{}' (was the benchmark run on another graph?)",
                                                k, manifest.name));
            if ((spec->min && v < *spec->min) || (spec->max && v > *spec->max))
                throw TradeOffError(fmt::format("setting \"{}\"", it->setting),
                                    fmt::format("{} = {:g} is outside the knob's range in the pack '{}'", k, v, manifest.name));
            level.knobs[k] = v;
        }
        ladder.push_back(std::move(level));
    }
    return ladder;
}

std::string describe_trade_off_ladder(const std::vector<TradeOff>& front) {
    std::string s;
    for (std::size_t i = 0; i < front.size(); ++i) {
        const TradeOff& t = front[front.size() - 1 - i];
        s += fmt::format("{}  level {}: \"{}\", {:.1f} ms", i ? "\n" : "", i, t.setting, t.time_ms);
        if (!std::isnan(t.wrong_pct)) s += fmt::format(", {:.3f} % misclassified", t.wrong_pct);
        if (t.picture_mse > 0.0) s += fmt::format(", picture {:.1f} dB", -10.0 * std::log10(t.picture_mse));
    }
    return s;
}

}  // namespace fg
