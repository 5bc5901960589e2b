#include "formula_program.h"

#include <fmt/format.h>

#include "graph/literal.h"
#include <algorithm>
#include <functional>
#include <set>

namespace fg {

namespace {

using Rule = StageDerivative::Rule;

class FormulaResolver {
public:
    FormulaResolver(const NodeLibrary& lib, const std::vector<ParamDecl>& params, const std::string& node_id,
                    Diagnostics& diag)
        : lib_(lib), params_(params), node_id_(node_id), diag_(diag) {}

    std::shared_ptr<const FormulaProgram> resolve(const FormulaBody& body) {
        auto prog = std::make_shared<FormulaProgram>();
        prog_ = prog.get();
        std::size_t errors_before = diag_.error_count();
        prog->repeat = body.repeat;
        prog->julia = body.julia;
        prog->bound_radius = body.bound_radius;
        prog->orbit = orbit_type(body);
        prog->jacobian = wants_jacobian(body);
        bool has_power = false;
        for (const auto& group : body.groups) {
            prog->groups.push_back(resolve_group(group));
            for (const auto& s : prog->groups.back().stages) has_power |= s.def && s.def->derivative.rule == Rule::Power;
        }
        using Estimate = FormulaProgram::Estimate;
        prog->estimate = body.estimate == "log" || (body.estimate.empty() && has_power) ? Estimate::Log
                         : body.estimate == "box"                                      ? Estimate::Box
                         : body.estimate == "sheet"                                    ? Estimate::Sheet
                                                                                       : Estimate::Linear;
        prog->sheet_radius = body.sheet_radius;
        prog->linear_radius = body.linear_radius;
        prog->filled = body.filled;
        if (prog->orbit == ValueType::Vec4 && (prog->estimate == Estimate::Box || prog->estimate == Estimate::Sheet))
            diag_.error("the box and sheet estimates measure a 3D point; a quaternion formula uses \"linear\" or \"log\"",
                        body.pointer + "/estimate", node_id_);
        for (const auto& seg : body.schedule)
            for (std::size_t g = 0; g < body.groups.size(); ++g)
                if (body.groups[g].name == seg.group) prog->segments.push_back({static_cast<int>(g), seg.count});
        if (body.schedule.empty()) prog->segments.push_back({0, 0});
        if (prog->segments.back().count == 0) prog->repeat = false;  // the last segment runs to the end
        if (diag_.error_count() != errors_before) return nullptr;
        return prog;
    }

private:
    const NodeLibrary& lib_;
    const std::vector<ParamDecl>& params_;
    const std::string& node_id_;
    Diagnostics& diag_;
    FormulaProgram* prog_ = nullptr;

    // vec4 when a stage works on quaternions, else vec3; stages of both kinds cannot share an orbit.
    ValueType orbit_type(const FormulaBody& body) {
        const GraphNode* first3 = nullptr;
        const GraphNode* first4 = nullptr;
        for (const auto& g : body.groups)
            for (const auto& n : g.nodes)
                if (const NodeDefinition* d = lib_.find(n.type);
                    d && d->is_stage() && !d->inputs.empty() && d->inputs[0].type.concrete) {
                    if (*d->inputs[0].type.concrete == ValueType::Vec4) first4 = first4 ? first4 : &n;
                    else first3 = first3 ? first3 : &n;
                }
        if (first3 && first4)
            diag_.error(fmt::format("stage \"{}\" ({}) works on 3D points and \"{}\" ({}) on quaternions: one formula "
                                    "carries one kind of orbit",
                                    first3->id, first3->type, first4->id, first4->type),
                        first4->pointer + "/type", node_id_);
        return first4 ? ValueType::Vec4 : ValueType::Vec3;
    }

    int param_input(const std::string& name) {
        for (std::size_t i = 0; i < prog_->params.size(); ++i)
            if (prog_->params[i] == name) return kFormulaFixedPorts + static_cast<int>(i);
        prog_->params.push_back(name);
        return kFormulaFixedPorts + static_cast<int>(prog_->params.size()) - 1;
    }

    // Scalar unless the body holds maths nodes or reads a stage.orbit node, or asks for it.
    bool wants_jacobian(const FormulaBody& body) {
        const GraphNode* needs = nullptr;
        for (const auto& g : body.groups)
            for (const auto& n : g.nodes)
                if (const NodeDefinition* d = lib_.find(n.type);
                    d && (!d->is_stage() || d->derivative.rule == Rule::Orbit) && !needs)
                    needs = &n;
        if (body.derivative == "scalar" && needs)
            diag_.error(fmt::format("node \"{}\" ({}) needs the running Jacobian: a scalar derivative covers stages only",
                                    needs->id, needs->type),
                        body.pointer + "/derivative", node_id_);
        return body.derivative == "jacobian" || (body.derivative.empty() && needs);
    }

    // A node's place in evaluation order: after every node it reads. stage.orbit nodes are not
    // placed; reading one names the group's entry point, c or the iteration index.
    FormulaGroupProgram resolve_group(const FormulaGroup& group) {
        FormulaGroupProgram out;
        out.name = group.name;
        std::map<std::string, const GraphNode*> by_id;
        for (const auto& n : group.nodes) by_id[n.id] = &n;
        std::map<std::string, int> index;
        std::vector<bool> varies;  // per placed node: does any of its inputs move with the orbit
        auto is_orbit_source = [&](const GraphNode& n) {
            const NodeDefinition* d = lib_.find(n.type);
            return d && d->derivative.rule == Rule::Orbit;
        };
        std::function<int(const GraphNode&)> place = [&](const GraphNode& n) -> int {
            if (auto it = index.find(n.id); it != index.end()) return it->second;
            for (const auto& [port, b] : n.inputs)
                if (b.kind == Binding::Kind::Node)
                    if (auto src = by_id.find(b.node); src != by_id.end() && !is_orbit_source(*src->second)) place(*src->second);
            FormulaStage s = resolve_stage(n, by_id, index, out, varies);
            index[n.id] = static_cast<int>(out.stages.size());
            out.stages.push_back(std::move(s));
            return index[n.id];
        };
        for (const auto& n : group.nodes)
            if (!is_orbit_source(n)) place(n);
        auto z = index.find(group.z_node);
        if (z == index.end()) {
            if (by_id.count(group.z_node))
                diag_.error("\"z\" names the orbit source: a group changes z through at least one node", group.pointer + "/z",
                            node_id_);
            return out;
        }
        out.z_out = z->second;
        const FormulaStage& last = out.stages[static_cast<std::size_t>(out.z_out)];
        if (last.def && !last.def->outputs.empty() && last.output_type(0) != prog_->orbit)
            diag_.error(fmt::format("\"z\" names node \"{}\", whose first output is {}; the orbit is {}", last.id,
                                    type_name(last.output_type(0)), type_name(prog_->orbit)),
                        group.pointer + "/z", node_id_);
        else if (prog_->jacobian && last.def && (last.tangent_outputs.empty() || last.tangent_outputs[0] != 0))
            diag_.error(fmt::format("node \"{}\" ({}) leaves the group as z, and its tangent rule does not cover its "
                                    "first output",
                                    last.id, last.def->type),
                        group.pointer + "/z", node_id_);
        return out;
    }

    // A body's $param feeds a port of its own type, an int one a float port, and a float one a
    // vector port (broadcast, as literals are: `splat`).
    void check_param(const std::string& name, ValueType want, const PortDefinition& port, const GraphNode& n, FormulaArg& a) {
        for (const auto& decl : params_) {
            if (decl.name != name) continue;
            if (decl.type == ValueType::Float && is_vector(want))
                a.splat = component_count(want);
            else if (decl.type != want && !(decl.type == ValueType::Int && want == ValueType::Float))
                diag_.error(fmt::format("type mismatch: input \"{}\" of {} is {}, but parameter \"${}\" is {}", port.name,
                                        n.type, type_name(want), name, type_name(decl.type)),
                            n.pointer + "/inputs/" + port.name, node_id_);
        }
    }

    std::optional<ValueType> param_type(const std::string& name) const {
        for (const auto& decl : params_)
            if (decl.name == name) return decl.type;
        return std::nullopt;
    }

    // What a wire from node `b.node` of this group names.
    FormulaArg wired(const Binding& b, const std::map<std::string, const GraphNode*>& by_id,
                     const std::map<std::string, int>& index, const FormulaGroupProgram& out) {
        FormulaArg a;
        a.kind = FormulaArg::Kind::Orbit;
        const GraphNode* src = by_id.at(b.node);
        const NodeDefinition* d = lib_.find(src->type);
        if (d && d->derivative.rule == Rule::Orbit) {
            if (b.port == "c") a.kind = FormulaArg::Kind::C;
            else if (b.port == "iteration") a.kind = FormulaArg::Kind::Iteration;
            return a;  // "z" or unnamed: the entry point
        }
        a.stage = index.at(b.node);
        const FormulaStage& from = out.stages[static_cast<std::size_t>(a.stage)];
        if (from.def && !b.port.empty())
            for (std::size_t o = 0; o < from.def->outputs.size(); ++o)
                if (from.def->outputs[o].name == b.port) a.output = static_cast<int>(o);
        return a;
    }

    ValueType arg_type(const FormulaArg& a, const FormulaGroupProgram& out) const {
        switch (a.kind) {
            case FormulaArg::Kind::Orbit:
                return a.stage < 0 ? prog_->orbit
                                   : out.stages[static_cast<std::size_t>(a.stage)].output_type(static_cast<std::size_t>(a.output));
            case FormulaArg::Kind::C: return prog_->orbit;
            case FormulaArg::Kind::Iteration: return ValueType::Float;
            case FormulaArg::Kind::Input: return ValueType::Float;  // refined by check_param
            case FormulaArg::Kind::Constant: break;
        }
        return a.constant.type;
    }

    bool arg_varies(const FormulaArg& a, const std::vector<bool>& varies) const {
        switch (a.kind) {
            case FormulaArg::Kind::Orbit: return a.stage < 0 || varies[static_cast<std::size_t>(a.stage)];
            case FormulaArg::Kind::C: return !prog_->julia;
            default: return false;
        }
    }

    std::string describe_arg(const FormulaArg& a, const FormulaGroupProgram& out) const {
        switch (a.kind) {
            case FormulaArg::Kind::Orbit: {
                if (a.stage < 0) return "the orbit point z";
                const FormulaStage& s = out.stages[static_cast<std::size_t>(a.stage)];
                return fmt::format("\"{}.{}\"", s.id, s.def ? s.def->outputs[static_cast<std::size_t>(a.output)].name : "");
            }
            case FormulaArg::Kind::C: return "c";
            case FormulaArg::Kind::Iteration: return "the iteration index";
            default: return "a value";
        }
    }

    FormulaStage resolve_stage(const GraphNode& n, const std::map<std::string, const GraphNode*>& by_id,
                               const std::map<std::string, int>& index, const FormulaGroupProgram& out,
                               std::vector<bool>& varies) {
        FormulaStage s;
        s.id = n.id;
        s.pointer = n.pointer;
        s.def = lib_.find(n.type);
        varies.push_back(false);
        if (!s.def) return s;  // reported by the loader
        const auto& d = s.def->derivative;
        const bool stage = s.def->is_stage();
        // Each input's argument, before the generic type is known.
        std::vector<const Binding*> bindings;
        for (std::size_t i = 0; i < s.def->inputs.size(); ++i) {
            const auto& port = s.def->inputs[i];
            FormulaArg a;
            auto b = n.inputs.find(port.name);
            bindings.push_back(b == n.inputs.end() ? nullptr : &b->second);
            if (b == n.inputs.end()) {
                if (stage && i == 0) {
                    a.kind = FormulaArg::Kind::Orbit;
                } else if (stage && port.name == "c" && d.rule == Rule::AddC) {
                    a.kind = FormulaArg::Kind::C;
                } else if (!port.default_value) {
                    diag_.error(fmt::format("node \"{}\" ({}) needs its input \"{}\"", n.id, n.type, port.name), n.pointer,
                                node_id_);
                } else {
                    a.constant = *port.default_value;
                }
            } else if (b->second.kind == Binding::Kind::Param) {
                a.kind = FormulaArg::Kind::Input;
                a.input = param_input(b->second.param);
            } else if (b->second.kind == Binding::Kind::Literal) {
                a.constant = b->second.literal;
            } else if (b->second.kind == Binding::Kind::Node) {
                a = wired(b->second, by_id, index, out);
            }
            s.args.push_back(a);
        }
        // A generic node's T: a stage's is the orbit's; a maths node's, the type of what feeds its T
        // ports (they must agree), else the widest literal there.
        if (!s.def->generic.empty()) {
            std::optional<ValueType> t;
            if (stage) t = prog_->orbit;
            int widest = 1;
            for (std::size_t i = 0; i < s.args.size() && !stage; ++i) {
                if (!s.def->inputs[i].type.is_generic()) continue;
                const FormulaArg& a = s.args[i];
                if (a.kind == FormulaArg::Kind::Constant) {
                    widest = std::max(widest, component_count(a.constant.type));
                    continue;
                }
                ValueType have = a.kind == FormulaArg::Kind::Input
                                     ? param_type(bindings[i]->param).value_or(ValueType::Float)
                                     : arg_type(a, out);
                if (!t) t = have;
                else if (*t != have)
                    diag_.error(fmt::format("type mismatch: input \"{}\" of {} is {} and another of its inputs is {}; they "
                                            "must be the same type",
                                            s.def->inputs[i].name, n.type, type_name(have), type_name(*t)),
                                n.pointer + "/inputs/" + s.def->inputs[i].name, node_id_);
            }
            if (!t) t = float_vector(widest);
            if (std::find(s.def->generic.begin(), s.def->generic.end(), *t) == s.def->generic.end()) {
                std::string allowed;
                for (auto g : s.def->generic) allowed += std::string(allowed.empty() ? "" : ", ") + std::string(type_name(g));
                diag_.error(fmt::format("{} works on {}, not {}", n.type, allowed, type_name(*t)), n.pointer, node_id_);
                t = s.def->generic.front();
            }
            s.generic = *t;
        }
        for (std::size_t i = 0; i < s.args.size(); ++i) {
            FormulaArg& a = s.args[i];
            const auto& port = s.def->inputs[i];
            const ValueType want = s.input_type(i);
            const std::string at = bindings[i] ? bindings[i]->pointer : n.pointer;
            if (a.kind == FormulaArg::Kind::Constant && bindings[i]) {
                if (auto c = coerce_literal(a.constant, want, {at, node_id_}, diag_)) a.constant = *c;
            } else if (a.kind == FormulaArg::Kind::Input) {
                check_param(bindings[i]->param, want, port, n, a);
            } else if (a.kind != FormulaArg::Kind::Constant && arg_type(a, out) != want) {
                diag_.error(fmt::format("type mismatch: input \"{}\" of {} is {}, but {} is {}", port.name, n.type,
                                        type_name(want), describe_arg(a, out), type_name(arg_type(a, out))),
                            at, node_id_);
            }
            if (!arg_varies(a, varies)) continue;
            varies.back() = true;
            // What moves with the orbit must move through a derivative rule.
            const bool in_rule = std::find(s.def->tangent.inputs.begin(), s.def->tangent.inputs.end(), port.name) !=
                                 s.def->tangent.inputs.end();
            const bool scalar_ok = stage && (i == 0 || (d.rule == Rule::AddC && port.name == "c" &&
                                                        a.kind == FormulaArg::Kind::C));
            if (prog_->jacobian ? !in_rule : !scalar_ok)
                diag_.error(fmt::format("input \"{}\" of \"{}\" ({}) takes {}, which moves with the orbit, and {}",
                                        port.name, n.id, n.type, describe_arg(a, out),
                                        prog_->jacobian ? "the node's tangent rule holds that input constant"
                                                        : "a stage's derivative rule covers only its z"),
                            at, node_id_);
            else if (a.kind == FormulaArg::Kind::Orbit && a.stage >= 0 && prog_->jacobian) {
                const FormulaStage& from = out.stages[static_cast<std::size_t>(a.stage)];
                if (std::find(from.tangent_outputs.begin(), from.tangent_outputs.end(), a.output) == from.tangent_outputs.end())
                    diag_.error(fmt::format("input \"{}\" of \"{}\" takes {}, which has no tangent rule", port.name, n.id,
                                            describe_arg(a, out)),
                                at, node_id_);
            }
        }
        if (prog_->jacobian && s.def->tangent.empty())
            diag_.error(fmt::format("stage \"{}\" ({}) has no tangent rule yet: a formula with maths nodes carries a running "
                                    "Jacobian, and this stage declares only its scalar factor (fgc nodes stage marks those "
                                    "with tangents)",
                                    n.id, n.type),
                        n.pointer + "/type", node_id_);
        for (const auto& name : s.def->tangent.inputs)
            for (std::size_t i = 0; i < s.def->inputs.size(); ++i)
                if (s.def->inputs[i].name == name) s.tangent_args.push_back(static_cast<int>(i));
        for (const auto& name : s.def->tangent.outputs)
            for (std::size_t o = 0; o < s.def->outputs.size(); ++o)
                if (s.def->outputs[o].name == name) s.tangent_outputs.push_back(static_cast<int>(o));
        for (std::size_t i = 0; i < s.def->inputs.size(); ++i)
            if (stage && d.rule == Rule::AddC && s.def->inputs[i].name == d.weight) s.weight_arg = static_cast<int>(i);
        for (std::size_t k = 0; k < s.def->outputs.size(); ++k)
            if (!d.factor.empty() && s.def->outputs[k].name == d.factor) s.factor_output = static_cast<int>(k);
        return s;
    }
};

}  // namespace

ValueType FormulaStage::output_type(std::size_t o) const {
    const PortType& t = def->outputs[o].type;
    return t.concrete ? *t.concrete : generic.value_or(ValueType::Vec3);
}

ValueType FormulaStage::input_type(std::size_t i) const {
    const PortType& t = def->inputs[i].type;
    return t.concrete ? *t.concrete : generic.value_or(ValueType::Vec3);
}

std::string FormulaProgram::describe() const {
    std::string text;
    if (jacobian) {
        text = "dz/dp carried through every node's tangent rule, dr times its norm (the largest stretch) each iteration";
    } else {
        for (const auto& g : groups) {
            std::string e = "dr";
            for (const auto& s : g.stages) {
                const auto& d = s.def->derivative;
                if (d.rule == Rule::Conformal) e += fmt::format(" * {}({})", d.factor, s.id);
                if (d.rule == Rule::Bound) e += fmt::format(" * {}({}) (norm bound)", d.factor, s.id);
                if (d.rule == Rule::Power) e += fmt::format(" * {}({}) (power map)", d.factor, s.id);
                if (d.rule == Rule::AddC && !julia) e = fmt::format("({} + |{}({})|)", e, d.weight, s.id);
            }
            text += fmt::format("{}{}: dr = {}", text.empty() ? "" : "; ", g.name, e);
        }
    }
    const char* estimates[] = {"r / dr", "0.5 log(r) r / dr", "(distance of z to the unit cube) / dr",
                               "(distance of z to the seed disc) / dr"};
    std::string distance = estimates[static_cast<int>(estimate)];
    if (estimate == Estimate::Linear && linear_radius != 0.0) distance = fmt::format("(r - {:g}) / dr", linear_radius);
    if (filled) distance += ", at most 0 where the orbit never escapes";
    return text + fmt::format("; dr guarded by the bias each iteration; distance {}", distance);
}

std::vector<std::pair<const NodeDefinition*, std::optional<ValueType>>> FormulaProgram::stage_definitions() const {
    std::vector<std::pair<const NodeDefinition*, std::optional<ValueType>>> defs;
    for (const auto& g : groups)
        for (const auto& s : g.stages)
            if (std::find(defs.begin(), defs.end(), std::make_pair(s.def, s.generic)) == defs.end())
                defs.emplace_back(s.def, s.generic);
    return defs;
}

std::shared_ptr<const FormulaProgram> build_formula_program(const FormulaBody& body, const NodeLibrary& lib,
                                                            const std::vector<ParamDecl>& params,
                                                            const std::string& node_id, Diagnostics& diag) {
    return FormulaResolver(lib, params, node_id, diag).resolve(body);
}

}  // namespace fg
