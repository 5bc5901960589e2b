#pragma once
// The head traces' trade-offs for the frame governor: `fgplay bench --sequence` writes, per scene,
// trade_offs_<scene>.json in the rows format of `fgplay bench`'s results.json (a trace is a view,
// a setting's cost its median GPU time per frame on that trace), so `fgplay xr --trade-offs` walks
// the settings as they measured on head motion: persistent lanes, reuse and shading history
// included, which a single still frame cannot judge.
#include <string>

#include <nlohmann/json.hpp>

#include "sequence_report.h"

namespace fg::bench {

// The scene's rows and their Pareto front ("trade_offs", cheapest first; empty with a "front_error"
// when no setting was measured without error on every trace).
nlohmann::json sequence_trade_offs_json(const SequenceReport& report, const std::string& scene);

}  // namespace fg::bench
