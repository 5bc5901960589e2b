#pragma once
// Graph format upgrades: each step rewrites a document of version N into version N + 1, so a graph
// written for any earlier version keeps loading. Steps are listed in upgrade.cpp, oldest first.
#include <nlohmann/json.hpp>

#include "common/diagnostics.h"

namespace fg {

// Upgrade `doc` from `version` to kGraphVersion in place; sets doc["version"]. Notes each step.
bool upgrade_graph(nlohmann::json& doc, int version, Diagnostics& diag);

}  // namespace fg
