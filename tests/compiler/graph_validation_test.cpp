// Bad graphs get clear errors naming the node and the JSON pointer, all of them in one run, and
// never a crash or a pack.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "test_support.h"

using fg::test::check_front;
using fg::test::has_error;
using fg::test::minimal_graph;
using nlohmann::json;

TEST(GraphValidation, the_minimal_graph_is_valid) {
    auto diag = check_front(minimal_graph());
    EXPECT_FALSE(diag.has_errors()) << diag.format();
}

TEST(GraphValidation, an_empty_file_is_reported_as_empty) {
    auto diag = check_front(std::string("  \n"));
    EXPECT_TRUE(has_error(diag, "", "", "empty"));
}

TEST(GraphValidation, text_that_is_not_json_is_reported_with_line_and_column) {
    auto diag = check_front(std::string("{\n  \"format\": fractograph\n}"));
    EXPECT_TRUE(has_error(diag, "", "", "line 2, column"));
}

TEST(GraphValidation, a_truncated_file_says_it_ends_early) {
    std::string text = minimal_graph().dump(2);
    auto diag = check_front(text.substr(0, text.size() / 2));
    EXPECT_TRUE(has_error(diag, "", "", "ends early"));
}

TEST(GraphValidation, a_document_of_another_format_is_refused) {
    auto g = minimal_graph();
    g["format"] = "materialx";
    EXPECT_TRUE(has_error(check_front(g), "/format", "", "not a Fractograph graph"));
}

TEST(GraphValidation, a_newer_format_version_is_refused_naming_both_versions) {
    auto g = minimal_graph();
    g["version"] = 7;
    EXPECT_TRUE(has_error(check_front(g), "/version", "", "version 7 is newer than this fgc understands (up to 1)"));
}

TEST(GraphValidation, an_unknown_node_type_is_reported_with_suggestions) {
    auto g = minimal_graph();
    g["nodes"][0]["type"] = "prim.shpere";
    EXPECT_TRUE(has_error(check_front(g), "/nodes/0/type", "ball", "did you mean prim.sphere"));
}

TEST(GraphValidation, an_unknown_input_port_lists_the_inputs) {
    auto g = minimal_graph();
    g["nodes"][0]["inputs"]["radious"] = 1.0;
    EXPECT_TRUE(has_error(check_front(g), "/nodes/0/inputs/radious", "ball", "its inputs are: p, radius"));
}

TEST(GraphValidation, a_reference_to_an_unknown_output_port_lists_the_outputs) {
    auto g = minimal_graph();
    g["outputs"]["distance"] = "ball.dist";
    EXPECT_TRUE(has_error(check_front(g), "/outputs/distance", "", "has no output \"dist\"; its outputs are: distance"));
}

TEST(GraphValidation, a_reference_to_an_unknown_node_is_reported) {
    auto g = minimal_graph();
    g["nodes"][1]["inputs"]["t"] = "nowhere.value";
    EXPECT_TRUE(has_error(check_front(g), "/nodes/1/inputs/t", "tone", "unknown node \"nowhere\""));
}

TEST(GraphValidation, a_type_mismatch_names_both_types_and_the_source) {
    auto g = minimal_graph();
    g["nodes"][1]["inputs"]["t"] = "tone2.color";
    g["nodes"].push_back({{"id", "tone2"}, {"type", "palette.cosine"}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/1/inputs/t", "tone",
                          "input \"t\" of palette.cosine is float, but output \"color\" of node \"tone2\" is vec3"));
}

TEST(GraphValidation, generic_inputs_of_different_types_are_a_mismatch) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "sum"}, {"type", "math.add"}, {"inputs", {{"a", "ball.distance"}, {"b", "tone.color"}}}});
    g["outputs"]["emission"] = "sum";
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/inputs/b", "sum", "needs them to be the same type"));
}

TEST(GraphValidation, a_cycle_is_reported_with_its_path) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "a"}, {"type", "math.add"}, {"inputs", {{"a", "b"}, {"b", 1.0}}}});
    g["nodes"].push_back({{"id", "b"}, {"type", "math.add"}, {"inputs", {{"a", "a"}, {"b", 1.0}}}});
    g["nodes"][0]["inputs"]["radius"] = "a";
    auto diag = check_front(g);
    bool found = false;
    for (const auto& d : diag.items())
        found |= d.message.find("cycle: ") != std::string::npos && d.message.find("a -> b -> a") != std::string::npos;
    EXPECT_TRUE(found) << diag.format();
}

TEST(GraphValidation, a_node_feeding_itself_is_a_cycle) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "loop"}, {"type", "math.add"}, {"inputs", {{"a", "loop"}, {"b", 1.0}}}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/inputs/a", "loop", "cycle: loop -> loop"));
}

TEST(GraphValidation, a_missing_required_input_is_reported) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "join"}, {"type", "op.union"}, {"inputs", {{"a", "ball"}}}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/inputs", "join", "missing required input \"b\""));
}

TEST(GraphValidation, a_duplicate_node_id_is_reported_at_the_second_node) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "ball"}, {"type", "prim.box"}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/id", "ball", "duplicate node id"));
}

TEST(GraphValidation, a_literal_of_the_wrong_shape_is_reported) {
    auto g = minimal_graph();
    g["nodes"][1]["inputs"]["a"] = json::array({1.0, 2.0});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/1/inputs/a", "tone", "expected vec3, got vec2 [1, 2]"));
}

TEST(GraphValidation, a_string_where_a_number_belongs_is_reported) {
    auto g = minimal_graph();
    g["nodes"][1]["inputs"]["a"] = json::array({1.0, "red", 2.0});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/1/inputs/a/1", "tone", "expected a number"));
}

TEST(GraphValidation, a_fractional_iteration_count_is_reported) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "bulb"}, {"type", "fractal.mandelbulb"}, {"inputs", {{"iterations", 7.5}}}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/inputs/iterations", "bulb", "expected int, got float 7.5"));
}

TEST(GraphValidation, an_out_of_range_literal_is_reported_with_the_range) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "bulb"}, {"type", "fractal.mandelbulb"}, {"inputs", {{"power", 100.0}}}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2/inputs/power", "bulb", "100 is out of range [2, 16]"));
}

TEST(GraphValidation, an_infinite_literal_is_refused_with_its_position) {
    std::string text = minimal_graph().dump(2);
    auto at = text.find("0.3");
    text.replace(at, 3, "1e999");
    auto diag = check_front(text);
    EXPECT_TRUE(has_error(diag, "", "", "number 1e999 at line"));
    EXPECT_TRUE(has_error(diag, "", "", "must be finite"));
}

TEST(GraphValidation, a_key_given_twice_is_reported) {
    std::string text = R"({"format": "fractograph-graph", "version": 1, "nodes": [
        {"id": "s", "type": "prim.sphere", "inputs": {"radius": 1.0, "radius": 2.0}}],
        "outputs": {"distance": "s"}})";
    EXPECT_TRUE(has_error(check_front(text), "/nodes/0/inputs/radius", "", "key given twice"));
}

TEST(GraphValidation, the_distance_output_is_required) {
    auto g = minimal_graph();
    g["outputs"].erase("distance");
    EXPECT_TRUE(has_error(check_front(g), "/outputs", "", "missing required output \"distance\""));
}

TEST(GraphValidation, a_medium_colour_without_its_density_is_reported) {
    auto g = minimal_graph();
    g["outputs"]["volume_color"] = json::array({1.0, 0.5, 0.2});
    EXPECT_TRUE(has_error(check_front(g), "/outputs/volume_color", "", "bind \"volume_density\" too"));
}

TEST(GraphValidation, a_lobe_roughness_without_its_reflectance_is_reported) {
    auto g = minimal_graph();
    g["outputs"]["roughness"] = 0.3;
    EXPECT_TRUE(has_error(check_front(g), "/outputs/roughness", "", "bind \"specular_color\" too"));
}

TEST(GraphValidation, an_unknown_output_name_lists_the_outputs) {
    auto g = minimal_graph();
    g["outputs"]["colour"] = "tone.color";
    EXPECT_TRUE(has_error(check_front(g), "/outputs/colour", "", "outputs are: distance, albedo"));
}

TEST(GraphValidation, an_unknown_parameter_lists_the_parameters) {
    auto g = minimal_graph();
    g["nodes"][0]["inputs"]["radius"] = "$size";
    EXPECT_TRUE(has_error(check_front(g), "/nodes/0/inputs/radius", "ball", "unknown parameter \"$size\"; params are: radius"));
}

TEST(GraphValidation, a_parameter_default_outside_its_range_is_reported) {
    auto g = minimal_graph();
    g["params"]["radius"]["default"] = 5.0;
    EXPECT_TRUE(has_error(check_front(g), "/params/radius/default", "", "5 is out of range [0.1, 2]"));
}

TEST(GraphValidation, a_parameter_of_the_wrong_type_for_its_port_is_a_mismatch) {
    auto g = minimal_graph();
    g["params"]["radius"]["type"] = "vec3";
    g["params"]["radius"]["default"] = json::array({1.0, 1.0, 1.0});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/0/inputs/radius", "ball", "but parameter \"$radius\" is vec3"));
}

TEST(GraphValidation, misspelt_fields_are_reported) {
    auto g = minimal_graph();
    g["nodez"] = json::array();
    g["nodes"][0]["input"] = json::object();
    g["scene"] = {{"fogg", json::object()}};
    auto diag = check_front(g);
    EXPECT_TRUE(has_error(diag, "/nodez", "", "unknown top-level field"));
    EXPECT_TRUE(has_error(diag, "/nodes/0/input", "ball", "unknown node field"));
    EXPECT_TRUE(has_error(diag, "/scene/fogg", "", "unknown scene setting"));
}

TEST(GraphValidation, several_errors_are_reported_in_one_run) {
    auto g = minimal_graph();
    g["nodes"][0]["type"] = "prim.nothing";
    g["nodes"][1]["inputs"]["a"] = "oops";
    g["nodes"].push_back({{"id", "ball"}, {"type", "prim.box"}});
    auto diag = check_front(g);
    EXPECT_GE(diag.error_count(), 3u) << diag.format();
}

TEST(GraphValidation, a_shading_node_cannot_feed_the_distance) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "ao"}, {"type", "light.fake_ao"}});
    g["nodes"].push_back({{"id", "d"}, {"type", "math.add"}, {"inputs", {{"a", "ball"}, {"b", "ao"}}}});
    g["outputs"]["distance"] = "d";
    EXPECT_TRUE(has_error(check_front(g), "/outputs/distance", "ao", "node \"ao\" (light.fake_ao), which only works while shading a hit"));
}

TEST(GraphValidation, a_custom_node_must_declare_its_lipschitz_bound) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "warp"},
                          {"type", "custom.glsl"},
                          {"ports", {{"inputs", {{{"name", "p"}, {"type", "vec3"}, {"default", "position"}}}},
                                     {"outputs", {{{"name", "d"}, {"type", "float"}}}}}},
                          {"code", "d = length(p) - 1.0;"}});
    EXPECT_TRUE(has_error(check_front(g), "/nodes/2", "warp", "must declare its Lipschitz bound"));
}

TEST(GraphValidation, error_messages_are_formatted_with_the_file_pointer_and_node) {
    auto g = minimal_graph();
    g["nodes"][0]["type"] = "prim.shpere";
    auto text = check_front(g).format("scene.json");
    EXPECT_NE(text.find("scene.json: error: /nodes/0/type (node 'ball'): unknown node type"), std::string::npos) << text;
}

TEST(GraphValidation, a_deeply_nested_document_is_refused_without_exhausting_the_stack) {
    const std::size_t depth = 200000;
    std::string text = R"({"format": "fractograph-graph", "version": 1, "comment": )" + std::string(depth, '[') +
                       std::string(depth, ']') + "}";
    EXPECT_TRUE(has_error(check_front(text), "/comment/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0", "", "nested more than 64 levels deep"));
}
