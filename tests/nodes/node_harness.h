#pragma once
// What the node tests share: the library's nodes with their generic instances, random inputs inside
// each port's declared range, a minimal graph around one node, and the evaluation shader that runs
// one node body at many points on the GPU (the CPU twin runs the same body in double precision).
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpu/cpu_value.h"
#include "graph/node_library.h"

namespace fg::test {

// Every node type of the built-in library except input.* (code generation supplies those), so nodes
// that other people add later are tested without anyone listing them.
std::vector<std::string> library_node_types();
const NodeDefinition& library_node(const std::string& type);
// Those of them that feed_distance(): shapes, distance operators, domain transforms, fractals.
std::vector<std::string> library_distance_node_types();

// The generic instances to test: nullopt for a non-generic node, else every type T may take.
std::vector<std::optional<ValueType>> instances_of(const NodeDefinition& def);
ValueType concrete_type(const PortType& type, std::optional<ValueType> generic);
std::string instance_name(const NodeDefinition& def, std::optional<ValueType> generic);

// Nodes whose bodies iterate a chaotic map (fractals): float and double orbits part ways near the
// surface, so a few points may disagree however correct the body is.
bool is_iterated(const NodeDefinition& def);

// One random value per input, inside the port's range (or a modest default range), already
// rounded to float so the GPU and the CPU twin see the same numbers.
std::vector<CpuValue> random_inputs(const NodeDefinition& def, std::optional<ValueType> generic, std::mt19937& rng);

// A graph in which node "n" is reached from an output: required distance inputs get small shapes,
// required points the position, other required values parameters; a domain transform (vec3 output
// "p") feeds a box; shading values go to a shading output. Optional inputs take the example's
// literals when `with_example` (the docs' example must be a valid setting).
nlohmann::json graph_around(const NodeDefinition& def, std::optional<ValueType> generic, bool with_example);
// Whether graph_around puts the node on the distance path (the node's Lipschitz rule then bounds
// the graph's distance).
bool feeds_distance(const NodeDefinition& def);

// GLSL of a compute shader that reads each point's inputs (one vec4 per input) from binding 0,
// calls the node body and writes its outputs (one vec4 each) to binding 1. Shade-context bodies
// see the scene distance of a unit sphere, as the CPU test installs it.
// With `in_double` the body, the prelude and the buffers are double (precision "double": the body
// lowered as fgc lowers it, the math from nodes/double_math.glsl).
std::string evaluation_shader(const NodeDefinition& def, std::optional<ValueType> generic, const std::string& prelude,
                              bool in_double = false);

// The scene distance that evaluation_shader() gives shade-context nodes, as a graph for the CPU twin.
const char* unit_sphere_scene();

}  // namespace fg::test
