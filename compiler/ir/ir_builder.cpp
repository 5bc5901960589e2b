#include "ir_builder.h"

#include <fmt/format.h>
#include <functional>
#include <set>

#include "codegen/formula_glsl.h"
#include "graph/literal.h"

namespace fg {

namespace {

// The function of a node whose body the graph carries: its IR index and id, '-' not being GLSL.
std::string generated_function_name(const char* kind, std::size_t index, const std::string& id) {
    std::string safe = id;
    for (char& c : safe)
        if (c == '-') c = '_';
    return fmt::format("fg_{}_{}_{}", kind, index, safe);
}

std::shared_ptr<NodeDefinition> make_custom_definition(const GraphNode& n, std::size_t index) {
    auto def = std::make_shared<NodeDefinition>();
    def->type = kCustomNodeType;
    def->summary = "custom GLSL";
    def->inputs = n.custom->inputs;
    def->outputs = n.custom->outputs;
    for (const auto& out : def->outputs) def->lipschitz[out.name] = n.custom->lipschitz;
    def->function = generated_function_name("custom", index, n.id);
    return def;
}

// A fractal.formula node's definition: the library's ports, then one input per graph parameter
// its body uses, and a function of its own whose body formula_glsl() writes.
std::shared_ptr<NodeDefinition> make_formula_definition(const NodeDefinition& library_def, const FormulaProgram& prog,
                                                        const Graph& g, const GraphNode& n, std::size_t index) {
    auto def = std::make_shared<NodeDefinition>(library_def);
    for (const auto& param : prog.params) {
        PortDefinition port;
        port.name = formula_param_input(param);
        const ParamDecl* decl = g.find_param(param);
        port.type.concrete = decl ? decl->type : ValueType::Float;
        def->inputs.push_back(port);
    }
    def->running_derivative = prog.describe();
    // The seed disc's estimate moves up to twice as fast as the point (measured: docs/fractals.md).
    if (prog.estimate == FormulaProgram::Estimate::Sheet) def->lipschitz["distance"] = "2 * L(p)";
    def->function = generated_function_name("formula", index, n.id);
    return def;
}

class IrBuilder {
public:
    IrBuilder(const Graph& g, const NodeLibrary& lib, Diagnostics& diag) : g_(g), lib_(lib), diag_(diag) {}

    std::optional<IrGraph> build() {
        ir_.name = g_.name;
        ir_.params = g_.params;
        ir_.scene = g_.scene;
        ir_.source = g_.source;
        order_live_nodes();
        for (const GraphNode* n : order_) lower_node(*n);
        for (const auto& [name, b] : g_.outputs) lower_output(name, b);
        if (diag_.has_errors()) return std::nullopt;
        return std::move(ir_);
    }

private:
    const Graph& g_;
    const NodeLibrary& lib_;
    Diagnostics& diag_;
    IrGraph ir_;
    std::vector<const GraphNode*> order_;
    std::map<std::string, int> index_;  // graph node id -> IR index
    std::map<std::string, ImplicitSource> implicit_alias_;  // input.* nodes: the value they name

    const NodeDefinition* def_of(const GraphNode& n) const { return lib_.find(n.type); }

    // Depth-first from the outputs: post-order is a valid evaluation order, and whatever is not
    // visited is dead.
    void order_live_nodes() {
        std::set<std::string> seen;
        std::function<void(const std::string&)> visit = [&](const std::string& id) {
            if (!seen.insert(id).second) return;
            const GraphNode* n = g_.find_node(id);
            if (!n) return;
            for (const auto& [_, b] : n->inputs)
                if (b.kind == Binding::Kind::Node) visit(b.node);
            order_.push_back(n);
        };
        for (const auto& [_, b] : g_.outputs)
            if (b.kind == Binding::Kind::Node) visit(b.node);
        for (const auto& n : g_.nodes)
            if (!seen.count(n.id))
                diag_.note(fmt::format("node \"{}\" reaches no output and is removed", n.id), n.pointer, n.id);
    }

    // Resolve a binding to an IR input (type not yet checked against the port).
    std::optional<IrInput> resolve(const Binding& b, const std::string& for_node) {
        IrInput in;
        in.pointer = b.pointer;
        switch (b.kind) {
            case Binding::Kind::Literal:
                in.kind = IrInput::Kind::Constant;
                in.constant = b.literal;
                in.source_type = b.literal.type;
                return in;
            case Binding::Kind::Param:
                for (std::size_t i = 0; i < ir_.params.size(); ++i)
                    if (ir_.params[i].name == b.param) {
                        in.kind = IrInput::Kind::Param;
                        in.param = static_cast<int>(i);
                        in.source_type = ir_.params[i].type;
                        return in;
                    }
                return std::nullopt;
            case Binding::Kind::Node: {
                if (auto alias = implicit_alias_.find(b.node); alias != implicit_alias_.end()) {
                    in.kind = IrInput::Kind::Implicit;
                    in.implicit = alias->second;
                    in.source_type = implicit_source_type(alias->second);
                    return in;
                }
                auto it = index_.find(b.node);
                if (it == index_.end()) return std::nullopt;
                const IrNode& src = ir_.nodes[static_cast<std::size_t>(it->second)];
                int port = 0;
                if (!b.port.empty()) {
                    for (std::size_t i = 0; i < src.def->outputs.size(); ++i)
                        if (src.def->outputs[i].name == b.port) port = static_cast<int>(i);
                }
                (void)for_node;
                in.kind = IrInput::Kind::Node;
                in.node = it->second;
                in.port = port;
                in.source_type = src.output_types[static_cast<std::size_t>(port)];
                return in;
            }
        }
        return std::nullopt;
    }

    static std::string describe_source(const IrGraph& ir, const IrInput& in) {
        switch (in.kind) {
            case IrInput::Kind::Node: {
                const auto& src = ir.nodes[static_cast<std::size_t>(in.node)];
                return fmt::format("output \"{}\" of node \"{}\"", src.def->outputs[static_cast<std::size_t>(in.port)].name,
                                   src.id);
            }
            case IrInput::Kind::Param: return fmt::format("parameter \"${}\"", ir.params[static_cast<std::size_t>(in.param)].name);
            case IrInput::Kind::Implicit: return fmt::format("the {}", implicit_source_name(in.implicit));
            default: return fmt::format("literal {}", in.constant.text());
        }
    }

    // A value of type `have` may feed a port of type `want`: equal, or int widened to float.
    static bool assignable(ValueType have, ValueType want) {
        return have == want || (have == ValueType::Int && want == ValueType::Float);
    }

    void lower_node(const GraphNode& node) {
        IrNode n;
        n.id = node.id;
        n.pointer = node.pointer;
        GraphNode with_params;  // a formula node with its body's parameters as inputs of its own
        const GraphNode& gn = node.formula ? with_params : node;
        if (node.formula) {
            with_params = node;
            n.formula = build_formula_program(*node.formula, lib_, g_.params, node.id, diag_);
            const NodeDefinition* library_def = def_of(node);
            if (!n.formula || !library_def) return;
            n.custom_def = make_formula_definition(*library_def, *n.formula, g_, node, ir_.nodes.size());
            n.def = n.custom_def.get();
            n.custom_code = formula_glsl(*n.formula);
            n.custom_code_pointer = node.formula->pointer;
            for (const auto& param : n.formula->params) {
                Binding b;
                b.kind = Binding::Kind::Param;
                b.param = param;
                b.pointer = node.formula->pointer;
                with_params.inputs[formula_param_input(param)] = b;
            }
        } else if (gn.custom) {
            n.custom_def = make_custom_definition(gn, ir_.nodes.size());
            n.def = n.custom_def.get();
            n.custom_code = gn.custom->code;
            n.custom_code_pointer = gn.custom->code_pointer;
        } else {
            n.def = def_of(gn);
        }
        if (!n.def) return;
        if (n.def->builtin_input) {
            // input.<source> nodes name a runtime-supplied value; uses refer to it directly.
            if (auto source = parse_implicit_source(n.def->type.substr(6))) implicit_alias_[gn.id] = *source;
            return;
        }
        const NodeDefinition& def = *n.def;
        std::size_t errors_before = diag_.error_count();

        // Resolve each declared input: bound, defaulted, or implicit.
        std::vector<std::optional<IrInput>> resolved(def.inputs.size());
        for (std::size_t i = 0; i < def.inputs.size(); ++i) {
            const auto& port = def.inputs[i];
            auto b = gn.inputs.find(port.name);
            if (b != gn.inputs.end()) {
                resolved[i] = resolve(b->second, gn.id);
                if (!resolved[i]) {
                    diag_.error(fmt::format("input \"{}\" refers to something that could not be resolved", port.name),
                                b->second.pointer, gn.id);
                }
                continue;
            }
            IrInput in;
            in.pointer = gn.pointer + "/inputs/" + port.name;
            if (port.implicit != ImplicitSource::None) {
                in.kind = IrInput::Kind::Implicit;
                in.implicit = port.implicit;
                in.source_type = implicit_source_type(port.implicit);
            } else if (port.default_value) {
                in.kind = IrInput::Kind::Constant;
                in.constant = *port.default_value;
                in.source_type = in.constant.type;
            } else {
                continue;  // missing required input: reported by the loader
            }
            resolved[i] = in;
        }

        // Generic nodes: T is the type of the non-literal inputs on T ports, which must agree;
        // with only literals, the widest literal.
        if (!def.generic.empty()) {
            std::optional<ValueType> t;
            std::string first_port;
            for (std::size_t i = 0; i < def.inputs.size(); ++i) {
                if (!def.inputs[i].type.is_generic() || !resolved[i] || resolved[i]->kind == IrInput::Kind::Constant)
                    continue;
                ValueType have = resolved[i]->source_type;
                if (!t) {
                    t = have;
                    first_port = def.inputs[i].name;
                } else if (*t != have) {
                    diag_.error(fmt::format("type mismatch: input \"{}\" is {} ({}) but \"{}\" is {}; {} needs them "
                                            "to be the same type",
                                            def.inputs[i].name, type_name(have), describe_source(ir_, *resolved[i]),
                                            first_port, type_name(*t), def.type),
                                resolved[i]->pointer, gn.id);
                }
            }
            if (!t) {
                int widest = 1;
                for (std::size_t i = 0; i < def.inputs.size(); ++i)
                    if (def.inputs[i].type.is_generic() && resolved[i])
                        widest = std::max(widest, component_count(resolved[i]->source_type));
                t = float_vector(widest);
            }
            if (std::find(def.generic.begin(), def.generic.end(), *t) == def.generic.end()) {
                std::string allowed;
                for (auto g : def.generic) allowed += std::string(allowed.empty() ? "" : ", ") + std::string(type_name(g));
                diag_.error(fmt::format("{} works on {}, not {}", def.type, allowed, type_name(*t)), gn.pointer, gn.id);
                t = def.generic.front();
            }
            n.generic = *t;
        }

        auto concrete = [&](const PortType& pt) { return pt.concrete ? *pt.concrete : *n.generic; };
        for (std::size_t i = 0; i < def.inputs.size(); ++i) {
            if (!resolved[i]) continue;
            IrInput in = *resolved[i];
            const auto& port = def.inputs[i];
            ValueType want = concrete(port.type);
            in.type = want;
            if (in.kind == IrInput::Kind::Constant) {
                LiteralSite site{in.pointer, gn.id};
                auto c = coerce_literal(in.constant, want, site, diag_);
                if (!c) continue;
                in.constant = *c;
                in.source_type = want;
                if (!port.knob.empty()) in.kind = IrInput::Kind::Knob;
            } else if (!assignable(in.source_type, want)) {
                diag_.error(fmt::format("type mismatch: input \"{}\" of {} is {}, but {} is {}", port.name, def.type,
                                        type_name(want), describe_source(ir_, in), type_name(in.source_type)),
                            in.pointer, gn.id);
                continue;
            }
            n.inputs.push_back(in);
        }
        for (const auto& out : def.outputs) n.output_types.push_back(concrete(out.type));
        if (diag_.error_count() != errors_before || n.inputs.size() != def.inputs.size()) return;

        n.shade_only = def.context == NodeContext::Shade;
        for (const auto& in : n.inputs) {
            if (in.kind == IrInput::Kind::Implicit) {
                n.position_dependent |= in.implicit != ImplicitSource::Time;
                n.time_dependent |= in.implicit == ImplicitSource::Time;
                n.shade_only |= implicit_source_is_shade_only(in.implicit);
            }
            if (in.kind == IrInput::Kind::Node) {
                const auto& src = ir_.nodes[static_cast<std::size_t>(in.node)];
                n.position_dependent |= src.position_dependent;
                n.time_dependent |= src.time_dependent;
                n.shade_only |= src.shade_only;
            }
        }
        index_[gn.id] = static_cast<int>(ir_.nodes.size());
        ir_.nodes.push_back(std::move(n));
    }

    // The node that makes `node` shade-only: a shade-context node, or one reading a shade input.
    const IrNode& shade_root(int node) const {
        const IrNode& n = ir_.nodes[static_cast<std::size_t>(node)];
        if (n.def->context == NodeContext::Shade) return n;
        for (const auto& in : n.inputs) {
            if (in.kind == IrInput::Kind::Implicit && implicit_source_is_shade_only(in.implicit)) return n;
            if (in.kind == IrInput::Kind::Node && ir_.nodes[static_cast<std::size_t>(in.node)].shade_only)
                return shade_root(in.node);
        }
        return n;
    }

    void lower_output(const std::string& name, const Binding& b) {
        const GraphOutputSpec* spec = nullptr;
        for (const auto& s : graph_output_specs())
            if (name == s.name) spec = &s;
        if (!spec) return;
        auto in = resolve(b, {});
        if (!in) return;  // the node failed to lower: already reported
        in->type = spec->type;
        if (in->kind == IrInput::Kind::Constant) {
            in->source_type = spec->type;
        } else if (!assignable(in->source_type, spec->type)) {
            diag_.error(fmt::format("type mismatch: output \"{}\" is {}, but {} is {}", name, type_name(spec->type),
                                    describe_source(ir_, *in), type_name(in->source_type)),
                        b.pointer);
            return;
        }
        if (name == "distance" && in->kind == IrInput::Kind::Node &&
            ir_.nodes[static_cast<std::size_t>(in->node)].shade_only) {
            const IrNode& culprit = shade_root(in->node);
            diag_.error(fmt::format("the distance depends on node \"{}\" ({}), which only works while shading a hit "
                                    "(it reads the normal or the view, or calls the scene distance)",
                                    culprit.id, culprit.def->type),
                        b.pointer, culprit.id);
            return;
        }
        ir_.outputs[name] = *in;
    }
};

}  // namespace

std::optional<IrGraph> build_ir(const Graph& graph, const NodeLibrary& library, Diagnostics& diag) {
    return IrBuilder(graph, library, diag).build();
}

}  // namespace fg
