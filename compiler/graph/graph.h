#pragma once
// A graph as the author wrote it, after loading and validation: parameters, nodes with their
// input bindings, outputs and scene settings. Every element keeps its JSON pointer so later
// stages can report problems against the file.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/value_type.h"
#include "graph/formula_body.h"
#include "graph/node_definition.h"
#include "graph/scene_settings.h"

namespace fg {

inline constexpr const char* kGraphFormat = "fractograph-graph";
inline constexpr int kGraphVersion = 1;

struct ParamDecl {
    std::string name;
    ValueType type = ValueType::Float;
    Constant value;                          // the default
    std::optional<double> min, max;
    std::string doc;
    std::string pointer;
};

// What feeds a node input or a graph output.
struct Binding {
    enum class Kind { Node, Param, Literal } kind = Kind::Literal;
    std::string node;     // Kind::Node: source node id
    std::string port;     // Kind::Node: source output port (empty: the node's first output)
    std::string param;    // Kind::Param
    Constant literal;     // Kind::Literal (its own type; coerced when the port's type is known)
    std::string pointer;  // JSON pointer of the binding
};

// A custom-code node: the author's GLSL, with declared ports and Lipschitz rule.
struct CustomCode {
    std::vector<PortDefinition> inputs, outputs;
    std::string code;                  // the function body (statements)
    std::string lipschitz;             // rule in the Lipschitz rule language, applies to every output
    std::string code_pointer;          // /nodes/4/code
};

struct GraphNode {
    std::string id;
    std::string type;
    std::map<std::string, Binding> inputs;
    std::optional<CustomCode> custom;  // type "custom.glsl"
    std::shared_ptr<const FormulaBody> formula;  // type "fractal.formula"
    std::string pointer;               // /nodes/3
};

struct Graph {
    std::string name;
    std::string description;
    int version = kGraphVersion;
    std::vector<ParamDecl> params;
    std::vector<GraphNode> nodes;
    std::map<std::string, Binding> outputs;   // "distance", "albedo", ...
    SceneSettings scene;
    nlohmann::json source;                    // the document as loaded (after upgrades)

    const GraphNode* find_node(const std::string& id) const;
    const ParamDecl* find_param(const std::string& param) const;
};

inline constexpr const char* kCustomNodeType = "custom.glsl";
inline constexpr const char* kFormulaNodeType = "fractal.formula";

// The outputs a graph may bind, with their types and the effect binding each one adds.
struct GraphOutputSpec {
    const char* name;
    ValueType type;
    bool required;
    const char* doc;
};
const std::vector<GraphOutputSpec>& graph_output_specs();

}  // namespace fg
