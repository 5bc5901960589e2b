#include "cpu_formula.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <fmt/format.h>

namespace fg {

namespace glsl {
// The prelude's guards, compiled into the twin with the node bodies (cpu_nodes.cpp).
double fg_conservative_dr(double dr, double bias, double next);
double fg_scale_dr(double dr, double factor);
double fg_jacobian_norm(glm::dvec4 a, glm::dvec4 b, glm::dvec4 c);
double fg_escape_share(int done, int iterations, double r2_last, double r2, double bail2);
}  // namespace glsl

namespace {
using Rule = StageDerivative::Rule;
constexpr double kTiny = 1e-20;  // the prelude's FG_TINY
}  // namespace

std::shared_ptr<const CpuFormula> CpuFormula::create(std::shared_ptr<const FormulaProgram> program,
                                                     const std::string& node_id, const std::string& pointer,
                                                     Diagnostics& diag) {
    auto f = std::make_shared<CpuFormula>();
    for (const auto& g : program->groups) {
        if (g.stages.size() > kMaxStages) {
            diag.error(fmt::format("group \"{}\" has {} stages; the CPU twin runs at most {}", g.name, g.stages.size(),
                                   kMaxStages),
                       pointer, node_id);
            return nullptr;
        }
        auto& fns = f->functions_.emplace_back();
        auto& tangents = f->tangents_.emplace_back();
        for (const auto& s : g.stages) {
            if (s.def->inputs.size() > kMaxStageInputs || s.def->outputs.size() > kMaxStageOutputs) {
                diag.error(fmt::format("stage \"{}\" ({}) has more ports than the CPU twin passes ({} in, {} out)", s.id,
                                       s.def->type, kMaxStageInputs, kMaxStageOutputs),
                           s.pointer, node_id);
                return nullptr;
            }
            CpuNodeFunction fn = find_cpu_node(s.def->type, s.generic);
            if (!fn) {
                diag.error(fmt::format("stage \"{}\" ({}) has no CPU twin", s.id, s.def->type), s.pointer, node_id);
                return nullptr;
            }
            fns.push_back(fn);
            tangents.push_back(program->jacobian ? find_cpu_tangent(s.def->type, s.generic) : nullptr);
            if (program->jacobian && !tangents.back()) {
                diag.error(fmt::format("node \"{}\" ({}) has no tangent rule in the CPU twin", s.id, s.def->type), s.pointer,
                           node_id);
                return nullptr;
            }
        }
    }
    f->program_ = std::move(program);
    return f;
}

// An argument's value in this iteration.
CpuValue CpuFormula::argument(const FormulaArg& a, const CpuValue* in, const Orbit& orbit, const Scratch& scratch) const {
    switch (a.kind) {
        case FormulaArg::Kind::Orbit: return a.stage < 0 ? CpuValue::of(orbit.z) : scratch.outs[a.stage][a.output];
        case FormulaArg::Kind::C: return CpuValue::of(orbit.c);
        case FormulaArg::Kind::Iteration: return CpuValue::of(static_cast<double>(orbit.iteration));
        case FormulaArg::Kind::Input: return a.splat ? CpuValue::of(glm::dvec4(in[a.input].f())) : in[a.input];
        case FormulaArg::Kind::Constant: break;
    }
    return CpuValue::of(a.constant);
}

// One pass through a group: as formula_glsl()'s iteration.
void CpuFormula::iterate(int group, const CpuValue* in, Orbit& orbit, double bias, Scratch& scratch) const {
    const FormulaProgram& prog = *program_;
    const auto& g = prog.groups[static_cast<std::size_t>(group)];
    const auto& fns = functions_[static_cast<std::size_t>(group)];
    auto& outs = scratch.outs;
    auto& d = scratch.d;
    auto& args = scratch.args;
    for (std::size_t k = 0; k < g.stages.size(); ++k) {
        const FormulaStage& s = g.stages[k];
        for (std::size_t a = 0; a < s.args.size(); ++a) args[a] = argument(s.args[a], in, orbit, scratch);
        fns[k](args, outs[k]);
        int from = s.args[0].stage;
        double d_in = from < 0 ? orbit.dr : d[from];
        switch (s.def->derivative.rule) {
            case Rule::Conformal:
            case Rule::Bound:
            case Rule::Power: d[k] = glsl::fg_scale_dr(d_in, outs[k][s.factor_output].f()); break;
            case Rule::AddC: d[k] = prog.julia ? d_in : d_in + std::abs(args[s.weight_arg].f()); break;
            default: d[k] = d_in; break;
        }
    }
    orbit.z = outs[g.z_out][0].v4();
    orbit.dr = glsl::fg_conservative_dr(orbit.dr, bias, d[g.z_out]);
}

// One pass through a group carrying the Jacobian: as formula_glsl()'s jacobian_iteration.
void CpuFormula::iterate_jacobian(int group, const CpuValue* in, Orbit& orbit, double bias, Scratch& scratch,
                                  TangentScratch& ts) const {
    const FormulaProgram& prog = *program_;
    const auto& g = prog.groups[static_cast<std::size_t>(group)];
    const auto& fns = functions_[static_cast<std::size_t>(group)];
    const auto& tangent_fns = tangents_[static_cast<std::size_t>(group)];
    auto& outs = scratch.outs;
    auto& args = scratch.args;
    auto& tangents = ts.tangents;
    const double inv = 1.0 / orbit.dr;
    auto tangent = [&](const FormulaArg& a, int j) {
        switch (a.kind) {
            case FormulaArg::Kind::Orbit: return a.stage < 0 ? CpuValue::of(orbit.columns[j]) : tangents[a.stage][a.output][j];
            case FormulaArg::Kind::C:
                if (!prog.julia) {
                    glm::dvec4 e(0.0);
                    e[j] = inv;
                    return CpuValue::of(e);
                }
                break;
            default: break;
        }
        return CpuValue{};
    };
    for (std::size_t k = 0; k < g.stages.size(); ++k) {
        const FormulaStage& s = g.stages[k];
        for (std::size_t a = 0; a < s.args.size(); ++a) args[a] = argument(s.args[a], in, orbit, scratch);
        fns[k](args, outs[k]);
        for (int j = 0; j < 3; ++j) {
            for (std::size_t t = 0; t < s.tangent_args.size(); ++t)
                ts.args[t] = tangent(s.args[static_cast<std::size_t>(s.tangent_args[t])], j);
            tangent_fns[k](args, ts.args, ts.out);
            for (std::size_t t = 0; t < s.tangent_outputs.size(); ++t) tangents[k][s.tangent_outputs[t]][j] = ts.out[t];
        }
    }
    orbit.z = outs[g.z_out][0].v4();
    const auto& cols = tangents[g.z_out][0];
    const double next =
        glsl::fg_conservative_dr(orbit.dr, bias, glsl::fg_scale_dr(orbit.dr, glsl::fg_jacobian_norm(cols[0].v, cols[1].v, cols[2].v)));
    const double keep = orbit.dr / std::max(next, kTiny);
    for (int j = 0; j < 3; ++j) orbit.columns[j] = cols[j].v * keep;
    orbit.dr = next;
}

void CpuFormula::run(const CpuValue* in, CpuValue* out) const {
    const FormulaProgram& prog = *program_;
    // A 3D orbit is carried with w = 0 (3D stages write 0 there), a quaternion one from (p, w).
    const glm::dvec3 p = in[kFormulaP].v3();
    const bool quaternion = prog.orbit == ValueType::Vec4;
    const glm::dvec4 start(p, quaternion ? in[kFormulaW].f() : 0.0);
    const glm::dvec4 c = !prog.julia ? start : quaternion ? in[kFormulaC].v4() : glm::dvec4(in[kFormulaC].v3(), 0.0);
    const int iterations = in[kFormulaIterations].i();
    const double bail2 = in[kFormulaBailout].f() * in[kFormulaBailout].f(), bias = in[kFormulaBias].f();
    // A Jacobian formula's columns start as the identity (a 4D orbit's w does not move with p).
    Orbit orbit{start, c, {glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0)}, 1.0, 0};
    const glm::dvec4& z = orbit.z;
    double r2 = glm::dot(z, z), r2_last = r2;
    glm::dvec4 trap(std::abs(z.x), std::abs(z.y), std::abs(z.z), r2);
    int i = 0;
    Scratch scratch;
    std::unique_ptr<TangentScratch> tangents;
    if (prog.jacobian) tangents = std::make_unique<TangentScratch>();
    do {
        for (const auto& seg : prog.segments)
            for (int n = 0; (seg.count == 0 || n < seg.count) && i < iterations; ++n, ++i) {
                if (r2 > bail2) break;
                orbit.iteration = i;
                if (prog.jacobian) iterate_jacobian(seg.group, in, orbit, bias, scratch, *tangents);
                else iterate(seg.group, in, orbit, bias, scratch);
                r2_last = r2;
                r2 = glm::dot(z, z);
                trap = glm::min(trap, glm::dvec4(std::abs(z.x), std::abs(z.y), std::abs(z.z), r2));
            }
    } while (prog.repeat && i < iterations && r2 <= bail2);
    const double r = std::sqrt(r2), dr = orbit.dr;
    double distance = (r - prog.linear_radius) / std::max(dr, kTiny);
    switch (prog.estimate) {
        case FormulaProgram::Estimate::Linear: break;
        case FormulaProgram::Estimate::Log: distance = 0.5 * std::log(std::max(r, kTiny)) * r / std::max(dr, kTiny); break;
        case FormulaProgram::Estimate::Box: {
            glm::dvec3 q = glm::abs(glm::dvec3(z)) - glm::dvec3(1.0);
            distance = (glm::length(glm::max(q, glm::dvec3(0.0))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0)) /
                       std::max(dr, kTiny);
            break;
        }
        case FormulaProgram::Estimate::Sheet: {
            double rxy = std::sqrt(z.x * z.x + z.y * z.y);
            double seed = std::max(rxy - prog.sheet_radius, std::abs(rxy * z.z) / std::max(glm::length(glm::dvec3(z)), kTiny));
            distance = seed / std::max(dr, kTiny);
            break;
        }
    }
    if (prog.filled && r2 <= bail2) distance = std::min(distance, 0.0);
    if (prog.bound_radius > 0.0) {
        const double ball = prog.julia ? std::max(prog.bound_radius, quaternion ? glm::length(in[kFormulaC].v4())
                                                                                 : glm::length(in[kFormulaC].v3()))
                                       : prog.bound_radius;
        double reach = glm::length(p) - ball;
        if (reach > ball) distance = std::min(distance, reach);
    }
    out[0] = CpuValue::of(distance);
    out[1] = CpuValue::of(trap);
    out[2] = CpuValue::of(glsl::fg_escape_share(i, iterations, r2_last, r2, bail2));
}

}  // namespace fg
