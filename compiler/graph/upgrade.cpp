#include "upgrade.h"

#include <fmt/format.h>
#include <functional>
#include <vector>

#include "graph.h"

namespace fg {

namespace {

struct UpgradeStep {
    int from;                      // rewrites version `from` into `from + 1`
    const char* what;              // one line for the user
    std::function<bool(nlohmann::json&, Diagnostics&)> apply;
};

// Version 1 is the first published format: no steps yet. When the format changes, bump
// kGraphVersion and add {1, "...", ...} here; tests/compiler/graph_upgrade_test.cpp keeps the
// committed v1 graphs loading.
const std::vector<UpgradeStep>& steps() {
    static const std::vector<UpgradeStep> s{};
    return s;
}

}  // namespace

bool upgrade_graph(nlohmann::json& doc, int version, Diagnostics& diag) {
    for (int v = version; v < kGraphVersion; ++v) {
        const UpgradeStep* step = nullptr;
        for (const auto& s : steps())
            if (s.from == v) step = &s;
        if (!step) {
            diag.error(fmt::format("no upgrade from graph format version {} to {}", v, v + 1), "/version");
            return false;
        }
        if (!step->apply(doc, diag)) return false;
        diag.note(fmt::format("upgraded graph from format version {} to {}: {}", v, v + 1, step->what), "/version");
    }
    doc["version"] = kGraphVersion;
    return true;
}

}  // namespace fg
