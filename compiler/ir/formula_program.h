#pragma once
// A fractal.formula node's body, resolved: stages in evaluation order with their arguments, the
// schedule of groups, and what the compiler derived from the stages' declared derivatives (the
// estimate form). GLSL generation (codegen/formula_glsl.h) and the CPU twin (cpu/cpu_formula.h)
// both run exactly this.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "graph/graph.h"
#include "graph/node_library.h"

namespace fg {

// The formula node's own inputs, in nodes/fractal/formula.json's order; after them come one input
// per graph parameter the body uses.
enum FormulaPort { kFormulaP = 0, kFormulaC, kFormulaW, kFormulaIterations, kFormulaBailout, kFormulaBias, kFormulaFixedPorts };

struct FormulaArg {
    enum class Kind {
        Orbit,      // `stage` < 0: the point entering the group; else output `output` of node `stage`
        C,          // the formula's c: the sample point, or the Julia constant
        Iteration,  // the iteration index (float)
        Constant,   // a literal, or the port's default
        Input,      // the formula node's input `input` (a graph parameter)
    } kind = Kind::Constant;
    int stage = -1;
    int output = 0;
    Constant constant;
    int input = -1;
    int splat = 0;   // Input: a float parameter feeding a vector port of this many components
};

// A node of the body: a stage or a maths node, in evaluation order.
struct FormulaStage {
    std::string id;
    std::string pointer;
    const NodeDefinition* def = nullptr;
    std::optional<ValueType> generic;   // a generic node's T (a stage's is the orbit's type)
    std::vector<FormulaArg> args;   // one per def->inputs
    int factor_output = -1;         // Conformal and Power stages: the output holding the factor
    int weight_arg = -1;            // AddC stages: the argument holding the weight
    std::vector<int> tangent_args;      // the inputs of its tangent rule, as indices into args
    std::vector<int> tangent_outputs;   // the outputs of its tangent rule, as indices into outputs

    ValueType output_type(std::size_t o) const;
    ValueType input_type(std::size_t i) const;
};

struct FormulaGroupProgram {
    std::string name;
    std::vector<FormulaStage> stages;   // each node after the nodes it reads
    int z_out = 0;                      // the node whose first output leaves the group as z
};

struct FormulaSegmentProgram {
    int group = 0;
    int count = 0;   // 0: every iteration left
};

struct FormulaProgram {
    ValueType orbit = ValueType::Vec3;  // z: vec3, or vec4 for quaternion formulas
    std::vector<FormulaGroupProgram> groups;
    std::vector<FormulaSegmentProgram> segments;
    bool repeat = false;
    bool julia = false;
    // How dr is carried. Scalar: each stage's declared factor times dr (exact for conformal stages).
    // Jacobian: every node's tangent rule moves three tangents, the columns of dz/dp over dr, and
    // dr grows by their norm each iteration (the largest stretch of any direction): maths nodes
    // need it, and it is exact for any smooth composition within an iteration.
    bool jacobian = false;
    // The distance estimate: the last orbit point's distance to a seed shape, over dr.
    enum class Estimate {
        Linear,  // (|z| - linear_radius) / dr: folding and IFS formulas
        Log,     // 0.5 log|z| |z| / dr: power maps
        Box,     // the unit cube [-1, 1]^3: Menger-type IFS
        Sheet,   // Knighty's seed disc of radius sheet_radius in the plane z = 0: pseudo-Kleinian caves
    } estimate = Estimate::Linear;
    double sheet_radius = 100.0;
    double linear_radius = 0.0;         // Linear: (|z| - this) / dr
    bool filled = false;                // an orbit that never escapes: distance at most 0
    double bound_radius = 0.0;          // 0: none
    std::vector<std::string> params;    // the graph parameter behind each input from kFormulaFixedPorts on

    // The derivative the compiler composed, in words, for fgc info and the manifest.
    std::string describe() const;
    // Every node the body calls, once per definition and generic instance.
    std::vector<std::pair<const NodeDefinition*, std::optional<ValueType>>> stage_definitions() const;
};

// Resolves a loaded body against the library; problems are reported at the body's pointers.
// `params`: the graph's, whose types say where a float parameter is broadcast to a vector port.
std::shared_ptr<const FormulaProgram> build_formula_program(const FormulaBody& body, const NodeLibrary& lib,
                                                            const std::vector<ParamDecl>& params,
                                                            const std::string& node_id, Diagnostics& diag);

}  // namespace fg
