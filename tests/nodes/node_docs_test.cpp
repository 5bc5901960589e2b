// Every node is documented: a summary, a "why and when", a doc string per port, an example that
// names only real ports, and an entry in docs/nodes.md. (tests/docs checks that docs/nodes.md is
// exactly what `fgc nodes --markdown` writes; this says what each entry must contain.)
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "every_node.h"

namespace {

std::string node_reference() {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/docs/nodes.md", std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

class NodeDocs : public ::testing::TestWithParam<std::string> {};

// One test per node (each ctest test is a process): the checks are cheap, the processes are not.
TEST_P(NodeDocs, is_documented_with_an_example_a_lipschitz_rule_and_a_reference_entry) {
    const auto& def = fg::test::library_node(GetParam());
    EXPECT_GE(def.summary.size(), 10u) << def.type << ": the summary is missing or too short";
    EXPECT_GE(def.doc.size(), 40u) << def.type << ": the doc should say why and when to use the node";
    EXPECT_NE(def.doc, def.summary) << def.type << ": the doc repeats the summary";
    for (const auto& p : def.inputs) EXPECT_FALSE(p.doc.empty()) << def.type << ": input " << p.name << " has no doc";
    for (const auto& p : def.outputs) EXPECT_FALSE(p.doc.empty()) << def.type << ": output " << p.name << " has no doc";

    EXPECT_TRUE(def.example.is_object() && def.example.contains("inputs") && def.example["inputs"].is_object())
        << def.type << ": no \"example\": {\"inputs\": {...}}";
    if (def.example.contains("inputs") && def.example["inputs"].is_object())
        for (auto it = def.example["inputs"].begin(); it != def.example["inputs"].end(); ++it)
            EXPECT_TRUE(def.find_input(it.key())) << def.type << ": the example binds unknown input " << it.key();

    // An output without a rule counts as unbounded; a distance output must say how it behaves.
    EXPECT_FALSE(def.lipschitz.empty()) << def.type << " declares no Lipschitz rule";
    if (def.find_output("distance"))
        EXPECT_TRUE(def.lipschitz.count("distance")) << def.type << ": the distance output has no Lipschitz rule";

    EXPECT_NE(node_reference().find("### `" + def.type + "`"), std::string::npos)
        << "docs/nodes.md has no entry for " << def.type << ": run `build/compiler/fgc nodes --markdown > docs/nodes.md`";
}

FG_FOR_EVERY_NODE(NodeDocs);

}  // namespace
