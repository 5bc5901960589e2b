#include "upgrade.h"

#include <fmt/format.h>
#include <vector>

#include "graph.h"

namespace fg {

// Version 1 is the first published format: no steps yet. When the format changes, bump
// kGraphVersion and add {1, "...", ...} here; tests/compiler/graph_upgrade_test.cpp keeps the
// committed v1 graphs (tests/compiler/graphs/v1/) loading.
std::span<const UpgradeStep> graph_upgrade_steps() {
    static const std::vector<UpgradeStep> s{};
    return s;
}

bool upgrade_graph(nlohmann::json& doc, int version, int target, std::span<const UpgradeStep> steps,
                   Diagnostics& diag) {
    for (int v = version; v < target; ++v) {
        const UpgradeStep* step = nullptr;
        for (const auto& s : steps)
            if (s.from == v) step = &s;
        if (!step) {
            diag.error(fmt::format("no upgrade from graph format version {} to {}", v, v + 1), "/version");
            return false;
        }
        if (!step->apply(doc, diag)) return false;
        diag.note(fmt::format("upgraded graph from format version {} to {}: {}", v, v + 1, step->what), "/version");
    }
    doc["version"] = target;
    return true;
}

bool upgrade_graph(nlohmann::json& doc, int version, Diagnostics& diag) {
    return upgrade_graph(doc, version, kGraphVersion, graph_upgrade_steps(), diag);
}

}  // namespace fg
