#include <gtest/gtest.h>

#include "studio/node_preview.h"

namespace fg::studio {

TEST(NodePreview, TheSubgraphOfANodeHoldsItAndWhatItReadsFromOnly) {
    auto graph = nlohmann::ordered_json::parse(R"({
      "format": "fractograph-graph", "version": 1, "params": {"r": {"type": "float", "default": 0.5}},
      "nodes": [
        {"id": "tw", "type": "xform.twist", "inputs": {"rate": 0.5}},
        {"id": "box", "type": "prim.box", "inputs": {"p": "tw.p"}},
        {"id": "ball", "type": "prim.sphere", "inputs": {"radius": "$r"}},
        {"id": "both", "type": "op.union", "inputs": {"a": "box", "b": {"node": "ball", "port": "distance"}}},
        {"id": "paint", "type": "palette.cosine", "inputs": {"t": 0.3}}
      ],
      "outputs": {"distance": "both.distance", "albedo": "paint.color"},
      "scene": {"camera": {"position": [0, 0, 3]}}})");
    std::string error;
    auto sub = distance_subgraph(graph, "box", "distance", error);
    ASSERT_TRUE(sub) << error;
    ASSERT_EQ((*sub)["nodes"].size(), 2u);
    EXPECT_EQ((*sub)["nodes"][0]["id"], "tw");
    EXPECT_EQ((*sub)["outputs"], nlohmann::ordered_json({{"distance", "box.distance"}}));
    EXPECT_EQ((*sub)["params"], graph["params"]);
    EXPECT_EQ((*sub)["scene"], graph["scene"]);
    sub = distance_subgraph(graph, "both", "distance", error);
    EXPECT_EQ((*sub)["nodes"].size(), 4u);
    EXPECT_FALSE(distance_subgraph(graph, "nope", "distance", error));
}

}  // namespace fg::studio
