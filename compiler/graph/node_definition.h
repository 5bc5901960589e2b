#pragma once
// One node type of the library, read from nodes/<namespace>/<name>.json. Its implementation is the
// GLSL function in the .glsl file beside it; the same text compiles as C++ for the CPU twin.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/effects.h"
#include "common/value_type.h"

namespace fg {

// A port's type: a concrete type, or the node's generic type T (one of NodeDefinition::generic).
struct PortType {
    std::optional<ValueType> concrete;   // empty: generic T
    bool is_generic() const { return !concrete; }
    std::string text() const { return concrete ? std::string(type_name(*concrete)) : "T"; }
};

// What an unbound input takes: values the runtime supplies. Position and time exist everywhere;
// the others only while shading a hit (a node using them is shade-only).
// `light_sample`: a point on an area light's unit disc for this sample (xy) and whether offline
// samples accumulate (z 1; 0 in a single frame), GpuFrame.area_light.
enum class ImplicitSource { None, Position, Time, Light, LightDistance, LightSample, ToCamera, Normal };
// `light_distance` of a directional light: farther than anything a float scene holds.
constexpr double kDirectionalLightDistance = 1e30;

std::string_view implicit_source_name(ImplicitSource s);          // "position", "light", ...
std::optional<ImplicitSource> parse_implicit_source(std::string_view s);
ValueType implicit_source_type(ImplicitSource s);
bool implicit_source_is_shade_only(ImplicitSource s);

struct PortDefinition {
    std::string name;
    PortType type;
    std::string doc;
    std::optional<Constant> default_value;    // literal default (inputs)
    ImplicitSource implicit = ImplicitSource::None;  // "default": "position", "time", "light", ...
    std::optional<double> min, max;           // valid range of literals, checked per component
    std::string knob;                         // "iterations" / "bias" / "steps" / "rays": becomes a specialization constant
    std::optional<Effect> effect;             // outputs: using this output adds the effect
    bool required() const { return !default_value && implicit == ImplicitSource::None; }
};

// How a formula stage (a stage.* node, used inside a fractal.formula body) moves the running
// derivative dr of the orbit point z with respect to the sample point. The compiler composes these
// into the formula's dr; node authors declare them once and never write derivative code.
struct StageDerivative {
    enum class Rule {
        None,       // not a stage
        Isometry,   // lengths kept (reflections, rotations, translations, folds of those): dr unchanged
        Conformal,  // locally a similarity: dr *= the output `factor` (exact)
        Bound,      // not conformal: dr *= the output `factor`, the largest stretch of any direction (the
                    // Jacobian's norm), so the scalar derivative stays an upper bound
        Power,      // not conformal: dr *= the output `factor`, the conventional scalar estimate the bias
                    // guards; a formula with such a stage uses the logarithmic distance estimate
        AddC,       // z + weight * c: dr += |input `weight`| when c is the sample point
        Orbit,      // stage.orbit: no code; the compiler supplies the point entering the group, c and
                    // the iteration index to the body's other nodes
    } rule = Rule::None;
    std::string factor;   // Conformal, Bound, Power: the output holding the factor
    std::string weight;   // AddC: the input holding the weight
};

// A node's dual-number rule: its body file also defines <function_name>_tangent(every input,
// then the tangent of each input in `inputs`, then OUT the tangent of each output in `outputs`):
// how a small change of those inputs moves those outputs. Formulas with maths nodes run it on
// three tangents at once, a running Jacobian (ir/formula_program.h). Inputs left out are held
// constant: a body must not feed them anything that moves with the orbit.
struct TangentRule {
    std::vector<std::string> inputs;
    std::vector<std::string> outputs;
    bool empty() const { return outputs.empty(); }
};

enum class NodeContext {
    Any,    // pure function of its inputs: may feed the distance
    Shade,  // evaluated only at a hit (may call the scene distance, read the normal)
};

struct NodeDefinition {
    std::string type;          // "fractal.mandelbulb"
    std::string summary;       // one line
    std::string doc;           // why and when to use it
    NodeContext context = NodeContext::Any;
    std::vector<PortDefinition> inputs;
    std::vector<PortDefinition> outputs;
    std::vector<ValueType> generic;                 // types T may take; empty if not generic
    std::map<std::string, std::string> lipschitz;   // output name -> rule (see analysis/lipschitz_rule.h)
    std::string running_derivative;                 // the dr update the bias guards; non-empty for DE fractals
    StageDerivative derivative;                     // stage.* nodes: how z's derivative moves
    TangentRule tangent;                            // how small changes move through it (may be empty)
    std::vector<Effect> effects;                    // using the node adds these
    nlohmann::json example;                         // an example node ("inputs": {...}) for the docs
    std::string glsl;                               // the body: one function, function_name()
    std::string tangent_glsl;                       // the tangent rule's function, last in the body file
    int tangent_line = 1;                           // where it starts there
    std::string json_path;                          // where it came from, for messages
    std::string glsl_path;
    bool builtin_input = false;                     // input.* nodes: code generation supplies them
    std::string function;                           // set for custom-code nodes: their generated name

    std::string function_name() const;              // "fg_fractal_mandelbulb"
    const PortDefinition* find_input(const std::string& name) const;
    const PortDefinition* find_output(const std::string& name) const;
    std::string namespace_name() const;             // "fractal"
    bool generated_body() const { return type == "fractal.formula"; }  // its GLSL comes from its body graph
    bool is_stage() const { return derivative.rule != StageDerivative::Rule::None; }
    // What a formula body may hold: stages, and nodes with a tangent rule (maths).
    bool fits_in_formula_body() const { return is_stage() || !tangent.empty(); }
    bool has_glsl_body() const {
        return !builtin_input && !generated_body() && derivative.rule != StageDerivative::Rule::Orbit;
    }
    std::string tangent_function_name() const { return function_name() + "_tangent"; }
};

}  // namespace fg
