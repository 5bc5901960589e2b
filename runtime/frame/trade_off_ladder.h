#pragma once
// The frame governor's ladder from what `fgplay bench` measured for this graph (`fgplay xr
// --trade-offs results.json`): the Pareto front of its settings, most accurate first, so every
// step down buys time with the least error the benchmark found for it. A setting the benchmark
// saw beaten on both time and error is never on it.
#include <string>
#include <vector>

#include "frame/trade_off_front.h"
#include "pack/manifest.h"
#include "frame/frame_governor.h"

namespace fg {

// Throws TradeOffError when a setting uses a knob this pack does not have, or a value outside the
// knob's range (a front measured for another graph).
std::vector<GovernorLevel> trade_off_ladder(const PackManifest& manifest, const std::vector<TradeOff>& front);

// One line per level for the log: "level 0: \"naive ...\" 812 ms, 0.28 % misclassified".
std::string describe_trade_off_ladder(const std::vector<TradeOff>& front);

}  // namespace fg
