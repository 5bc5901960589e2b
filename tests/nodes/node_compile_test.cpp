// Every node compiles alone: a minimal graph around it (with the literals of its documented
// example) goes through the whole compiler, glslang and SPIR-V validation included, and the
// node's body is in the generated code rather than folded away.
#include <gtest/gtest.h>

#include "compiler.h"
#include "every_node.h"

namespace {

class NodeCompiles : public ::testing::TestWithParam<std::string> {};

TEST_P(NodeCompiles, alone_in_a_minimal_graph_with_its_example_settings) {
    const auto& def = fg::test::library_node(GetParam());
    for (auto generic : fg::test::instances_of(def)) {
        SCOPED_TRACE(fg::test::instance_name(def, generic));
        const auto graph = fg::test::graph_around(def, generic, true);
        fg::Diagnostics diag;
        auto result = fg::compile_graph(graph.dump(), fg::NodeLibrary::builtin(), {}, diag);
        ASSERT_TRUE(result) << diag.format() << "\ngraph: " << graph.dump(2);
        EXPECT_FALSE(diag.has_errors()) << diag.format();
        int at = result->ir.find("n");
        ASSERT_GE(at, 0) << "the node was folded or removed: " << graph.dump(2);
        EXPECT_EQ(result->ir.nodes[static_cast<std::size_t>(at)].generic, generic);
        bool called = false;
        for (const auto& pass : result->passes)
            called = called || pass.source.glsl.find(def.function_name() + "(") != std::string::npos;
        EXPECT_TRUE(called) << def.function_name() << " is in no pass";
    }
}

FG_FOR_EVERY_NODE(NodeCompiles);

}  // namespace
