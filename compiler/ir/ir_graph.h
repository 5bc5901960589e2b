#pragma once
// The typed IR: nodes in dependency order with every input resolved (defaults filled in, generic
// types instantiated, literals coerced), constants folded and nodes no output reaches removed.
// Code generation, the analyses and the CPU twin all read this form.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/value_type.h"
#include "graph/graph.h"
#include "graph/node_definition.h"
#include "ir/formula_program.h"

namespace fg {

struct IrInput {
    enum class Kind {
        Node,      // output `port` of IR node `node`
        Param,     // graph parameter `param` (a uniform)
        Constant,  // a literal or folded value
        Knob,      // an accuracy knob bound to a literal: a specialization constant (id in knob_id)
        Implicit,  // a value the runtime supplies: position, time, light, to_camera, normal
    } kind = Kind::Constant;
    ImplicitSource implicit = ImplicitSource::None;
    int node = -1;
    int port = 0;
    int param = -1;
    Constant constant;
    ValueType type = ValueType::Float;  // the type the consuming port receives
    ValueType source_type = ValueType::Float;  // the type produced (differs only for int -> float)
    int knob_id = 0;                           // Kind::Knob: specialization constant id
    std::string pointer;
};

struct IrNode {
    std::string id;
    const NodeDefinition* def = nullptr;         // library node, or custom_def.get()
    std::shared_ptr<NodeDefinition> custom_def;  // custom.glsl: a definition made from its ports
    std::string custom_code;
    std::string custom_code_pointer;
    std::shared_ptr<const FormulaProgram> formula;  // fractal.formula: its body (custom_code is its GLSL)
    std::optional<ValueType> generic;            // what T is for this node
    std::vector<IrInput> inputs;                 // one per def->inputs, same order
    std::vector<ValueType> output_types;         // one per def->outputs
    std::string pointer;
    bool position_dependent = false;             // varies with the sample point
    bool time_dependent = false;
    bool shade_only = false;                     // needs the shading context (normals, scene distance)
};

struct IrGraph {
    std::string name;
    std::vector<ParamDecl> params;
    std::vector<IrNode> nodes;                   // dependency order: inputs before users
    std::map<std::string, IrInput> outputs;      // graph outputs ("distance", ...)
    SceneSettings scene;
    nlohmann::json source;                       // the graph document

    int find(const std::string& id) const;
    ValueType output_type(const IrInput& in) const;
};

}  // namespace fg
