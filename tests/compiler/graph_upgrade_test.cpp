// Graphs written for an older format version keep loading: the committed version-1 graphs load and
// compile with today's compiler, and the upgrade walk applies each step in order, noting it.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "graph/graph_loader.h"
#include "graph/upgrade.h"
#include "test_support.h"

using namespace fg;
using fg::test::has_error;

namespace {

std::vector<std::filesystem::path> v1_graphs() {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(std::string(FG_SOURCE_DIR) + "/tests/compiler/graphs/v1"))
        if (e.path().extension() == ".json") out.push_back(e.path());
    return out;
}

}  // namespace

TEST(GraphUpgrade, every_committed_version_1_graph_loads_and_compiles_forever) {
    auto graphs = v1_graphs();
    ASSERT_FALSE(graphs.empty());
    for (const auto& path : graphs) {
        SCOPED_TRACE(path.string());
        std::string text = test::read_source_file("tests/compiler/graphs/v1/" + path.filename().string());
        ASSERT_NE(text.find("\"version\": 1,"), std::string::npos) << "the frozen graphs are version 1";
        Diagnostics diag;
        auto graph = load_graph(text, NodeLibrary::builtin(), diag);
        ASSERT_TRUE(graph) << diag.format();
        EXPECT_FALSE(diag.has_errors()) << diag.format();
        EXPECT_EQ(graph->version, kGraphVersion);
        EXPECT_FALSE(graph->nodes.empty());
        Diagnostics compile_diag;
        EXPECT_TRUE(test::compile_text(text, compile_diag)) << compile_diag.format();
    }
}

TEST(GraphUpgrade, steps_apply_in_order_and_each_is_noted) {
    std::vector<int> order;
    std::vector<UpgradeStep> steps{
        {2, "renamed port b to c", [&](nlohmann::json& d, Diagnostics&) { order.push_back(2); d["c"] = d["b"]; d.erase("b"); return true; }},
        {1, "renamed port a to b", [&](nlohmann::json& d, Diagnostics&) { order.push_back(1); d["b"] = d["a"]; d.erase("a"); return true; }},
    };
    nlohmann::json doc = {{"version", 1}, {"a", 42}};
    Diagnostics diag;
    ASSERT_TRUE(upgrade_graph(doc, 1, 3, steps, diag)) << diag.format();
    EXPECT_EQ(order, (std::vector<int>{1, 2}));
    EXPECT_EQ(doc["c"], 42);
    EXPECT_EQ(doc["version"], 3);
    std::size_t notes = 0;
    for (const auto& d : diag.items())
        if (d.severity == Severity::Note && d.message.find("upgraded graph from format version") != std::string::npos) ++notes;
    EXPECT_EQ(notes, 2u) << diag.format();
}

TEST(GraphUpgrade, a_missing_step_is_an_error_naming_both_versions) {
    std::vector<UpgradeStep> steps{{1, "one", [](nlohmann::json&, Diagnostics&) { return true; }}};
    nlohmann::json doc = {{"version", 1}};
    Diagnostics diag;
    EXPECT_FALSE(upgrade_graph(doc, 1, 3, steps, diag));
    EXPECT_TRUE(has_error(diag, "/version", "", "no upgrade from graph format version 2 to 3"));
}

TEST(GraphUpgrade, a_failing_step_stops_the_load) {
    std::vector<UpgradeStep> steps{
        {1, "fails", [](nlohmann::json&, Diagnostics& d) { d.error("cannot convert the old camera", "/scene/camera"); return false; }},
        {2, "never runs", [](nlohmann::json&, Diagnostics&) { ADD_FAILURE() << "ran after a failed step"; return true; }},
    };
    nlohmann::json doc = {{"version", 1}};
    Diagnostics diag;
    EXPECT_FALSE(upgrade_graph(doc, 1, 3, steps, diag));
    EXPECT_TRUE(has_error(diag, "/scene/camera", "", "cannot convert the old camera"));
}

TEST(GraphUpgrade, the_compilers_steps_cover_every_version_before_the_current_one) {
    for (int v = 1; v < kGraphVersion; ++v) {
        bool found = false;
        for (const auto& s : graph_upgrade_steps()) found = found || s.from == v;
        EXPECT_TRUE(found) << "no upgrade step from version " << v;
    }
    nlohmann::json doc = test::minimal_graph();
    Diagnostics diag;
    EXPECT_TRUE(upgrade_graph(doc, 1, diag)) << diag.format();
    EXPECT_EQ(doc["version"], kGraphVersion);
}

TEST(GraphUpgrade, version_0_does_not_exist) {
    auto g = test::minimal_graph();
    g["version"] = 0;
    EXPECT_TRUE(has_error(test::check_front(g), "/version", "", "version 0 does not exist"));
}
