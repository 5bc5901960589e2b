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
        bool has_power = false;
        for (const auto& group : body.groups) {
            prog->groups.push_back(resolve_group(group));
            for (const auto& s : prog->groups.back().stages) has_power |= s.def->derivative.rule == Rule::Power;
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
                if (const NodeDefinition* d = lib_.find(n.type); d && !d->inputs.empty() && d->inputs[0].type.concrete) {
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

    FormulaGroupProgram resolve_group(const FormulaGroup& group) {
        FormulaGroupProgram out;
        out.name = group.name;
        // Evaluation order: a stage after the stage its z comes from.
        std::map<std::string, const GraphNode*> by_id;
        for (const auto& n : group.nodes) by_id[n.id] = &n;
        std::map<std::string, int> index;
        std::function<int(const GraphNode&)> place = [&](const GraphNode& n) -> int {
            if (auto it = index.find(n.id); it != index.end()) return it->second;
            int from = -1;
            if (auto z = n.inputs.find("z"); z != n.inputs.end() && z->second.kind == Binding::Kind::Node)
                if (auto src = by_id.find(z->second.node); src != by_id.end()) from = place(*src->second);
            FormulaStage s = resolve_stage(n, from);
            index[n.id] = static_cast<int>(out.stages.size());
            out.stages.push_back(std::move(s));
            return index[n.id];
        };
        for (const auto& n : group.nodes) place(n);
        if (auto z = index.find(group.z_node); z != index.end()) out.z_out = z->second;
        return out;
    }

    // A body's $param feeds a port of its own type, an int one a float port, and a float one a
    // vector port (broadcast, as literals are: `splat`).
    void check_param(const std::string& name, const PortDefinition& port, const GraphNode& n, FormulaArg& a) {
        const ValueType want = port.type.concrete ? *port.type.concrete : prog_->orbit;
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

    FormulaStage resolve_stage(const GraphNode& n, int z_from) {
        FormulaStage s;
        s.id = n.id;
        s.pointer = n.pointer;
        s.def = lib_.find(n.type);
        if (!s.def) return s;  // reported by the loader
        if (!s.def->generic.empty()) s.generic = prog_->orbit;
        const auto& d = s.def->derivative;
        for (std::size_t i = 0; i < s.def->inputs.size(); ++i) {
            const auto& port = s.def->inputs[i];
            FormulaArg a;
            auto b = n.inputs.find(port.name);
            if (i == 0) {
                a.kind = FormulaArg::Kind::Orbit;
                a.stage = z_from;
            } else if (b == n.inputs.end() && port.name == "c" && d.rule == Rule::AddC) {
                a.kind = FormulaArg::Kind::C;
            } else if (b == n.inputs.end()) {
                if (!port.default_value) {
                    diag_.error(fmt::format("stage \"{}\" ({}) needs its input \"{}\"", n.id, n.type, port.name), n.pointer,
                                node_id_);
                    continue;
                }
                a.constant = *port.default_value;
            } else if (b->second.kind == Binding::Kind::Param) {
                a.kind = FormulaArg::Kind::Input;
                a.input = param_input(b->second.param);
                check_param(b->second.param, port, n, a);
            } else if (b->second.kind == Binding::Kind::Literal) {
                a.constant = b->second.literal;
                // A generic port takes the orbit's type; the loader could not know it.
                if (!port.type.concrete)
                    if (auto c = coerce_literal(a.constant, prog_->orbit, {b->second.pointer, node_id_}, diag_)) a.constant = *c;
            }
            s.args.push_back(a);
            if (d.rule == Rule::AddC && port.name == d.weight) s.weight_arg = static_cast<int>(i);
        }
        for (std::size_t k = 0; k < s.def->outputs.size(); ++k)
            if (!d.factor.empty() && s.def->outputs[k].name == d.factor) s.factor_output = static_cast<int>(k);
        return s;
    }
};

}  // namespace

std::string FormulaProgram::describe() const {
    std::string text;
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
