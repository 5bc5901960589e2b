#pragma once
// Graph format upgrades: each step rewrites a document of version N into version N + 1, so a graph
// written for any earlier version keeps loading. Steps are listed in upgrade.cpp, oldest first.
#include <functional>
#include <span>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"

namespace fg {

struct UpgradeStep {
    int from;                      // rewrites version `from` into `from + 1`
    const char* what;              // one line for the user
    std::function<bool(nlohmann::json&, Diagnostics&)> apply;
};

// The steps of this compiler, oldest first.
std::span<const UpgradeStep> graph_upgrade_steps();

// Upgrade `doc` from `version` to kGraphVersion in place; sets doc["version"]. Notes each step.
bool upgrade_graph(nlohmann::json& doc, int version, Diagnostics& diag);

// The same walk over any list of steps up to `target`: the machinery, testable before the format
// has a second version.
bool upgrade_graph(nlohmann::json& doc, int version, int target, std::span<const UpgradeStep> steps,
                   Diagnostics& diag);

}  // namespace fg
