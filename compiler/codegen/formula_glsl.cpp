#include "formula_glsl.h"

#include <fmt/format.h>

namespace fg {

namespace {

using Rule = StageDerivative::Rule;

std::string value(const FormulaProgram& prog, const FormulaArg& a) {
    switch (a.kind) {
        case FormulaArg::Kind::Orbit: return a.stage < 0 ? "fz_z" : fmt::format("fz_s{}_{}", a.stage, a.output);
        case FormulaArg::Kind::C: return "fz_c";
        case FormulaArg::Kind::Iteration: return "float(fz_i)";
        case FormulaArg::Kind::Input: {
            std::string v = formula_param_input(prog.params[static_cast<std::size_t>(a.input - kFormulaFixedPorts)]);
            return a.splat ? fmt::format("vec{}({})", a.splat, v) : v;
        }
        case FormulaArg::Kind::Constant: break;
    }
    return a.constant.glsl();
}

// Tangent j of an argument: d(value)/dp_j over dr. What does not move with the orbit has none.
std::string tangent(const FormulaProgram& prog, const FormulaArg& a, int j, ValueType type) {
    switch (a.kind) {
        case FormulaArg::Kind::Orbit:
            return a.stage < 0 ? fmt::format("fz_j{}", j) : fmt::format("fz_t{}_{}_{}", a.stage, a.output, j);
        case FormulaArg::Kind::C:
            if (!prog.julia) return fmt::format("fz_cj{}", j);
            break;
        default: break;
    }
    return fmt::format("{}(0.0)", type_name(type));
}

std::string arguments(const FormulaProgram& prog, const FormulaStage& s) {
    std::string args;
    for (std::size_t a = 0; a < s.args.size(); ++a) args += (a ? ", " : "") + value(prog, s.args[a]);
    return args;
}

// Each node's outputs fz_s<k>_<o>, and its call.
std::string call(const FormulaProgram& prog, const FormulaStage& s, std::size_t k, const std::string& indent) {
    std::string decl, args = arguments(prog, s);
    for (std::size_t o = 0; o < s.def->outputs.size(); ++o) {
        decl += fmt::format("{}{} fz_s{}_{};", decl.empty() ? "" : " ", type_name(s.output_type(o)), k, o);
        args += fmt::format(", fz_s{}_{}", k, o);
    }
    return fmt::format("{}{}  // {} ({})\n{}{}({});\n", indent, decl, s.id, s.def->type, indent, s.def->function_name(), args);
}

// One iteration of a group with scalar dr: each stage's derivative fz_d<k> from its z's.
std::string scalar_iteration(const FormulaProgram& prog, const FormulaGroupProgram& g, const std::string& indent) {
    std::string out;
    for (std::size_t k = 0; k < g.stages.size(); ++k) {
        const FormulaStage& s = g.stages[k];
        int from = s.args[0].stage;
        std::string d_in = from < 0 ? "fz_dr_in" : fmt::format("fz_d{}", from);
        std::string d;
        switch (s.def->derivative.rule) {
            case Rule::Conformal:
            case Rule::Bound:
            case Rule::Power: d = fmt::format("fg_scale_dr({}, fz_s{}_{})", d_in, k, s.factor_output); break;
            case Rule::AddC:
                d = prog.julia ? d_in : fmt::format("{} + abs({})", d_in, value(prog, s.args[static_cast<std::size_t>(s.weight_arg)]));
                break;
            default: d = d_in; break;
        }
        out += call(prog, s, k, indent);
        out += fmt::format("{}float fz_d{} = {};\n", indent, k, d);
    }
    out += fmt::format("{}fz_z = fz_s{}_0;\n", indent, g.z_out);
    out += fmt::format("{}fz_dr = fg_conservative_dr(fz_dr, bias, fz_d{});\n", indent, g.z_out);
    return out;
}

// One iteration of a group carrying the Jacobian: fz_j0..2 are the columns of dz/dp over dr; each
// node's tangent rule runs once per column (fz_t<k>_<o>_<j>). dr then grows by the columns' norm
// and they shrink by as much, so that dr * J stays dz/dp and J stays near unit size.
std::string jacobian_iteration(const FormulaProgram& prog, const FormulaGroupProgram& g, const std::string& indent) {
    const std::string orbit(type_name(prog.orbit));
    std::string out = fmt::format("{}float fz_inv = 1.0 / fz_dr;\n", indent);
    if (!prog.julia)
        for (int j = 0; j < 3; ++j)
            out += fmt::format("{}{} fz_cj{} = {}({}, {}, {}{});\n", indent, orbit, j, orbit, j == 0 ? "fz_inv" : "0.0",
                               j == 1 ? "fz_inv" : "0.0", j == 2 ? "fz_inv" : "0.0", prog.orbit == ValueType::Vec4 ? ", 0.0" : "");
    for (std::size_t k = 0; k < g.stages.size(); ++k) {
        const FormulaStage& s = g.stages[k];
        out += call(prog, s, k, indent);
        const std::string args = arguments(prog, s);
        for (int j = 0; j < 3; ++j) {
            std::string decl, targs = args;
            for (int i : s.tangent_args)
                targs += ", " + tangent(prog, s.args[static_cast<std::size_t>(i)], j, s.input_type(static_cast<std::size_t>(i)));
            for (int o : s.tangent_outputs) {
                decl += fmt::format("{}{} fz_t{}_{}_{};", decl.empty() ? "" : " ", type_name(s.output_type(static_cast<std::size_t>(o))), k, o, j);
                targs += fmt::format(", fz_t{}_{}_{}", k, o, j);
            }
            out += fmt::format("{}{}\n{}{}({});\n", indent, decl, indent, s.def->tangent_function_name(), targs);
        }
    }
    out += fmt::format("{}fz_z = fz_s{}_0;\n", indent, g.z_out);
    out += fmt::format("{}float fz_next = fg_conservative_dr(fz_dr, bias, fg_scale_dr(fz_dr, fg_jacobian_norm(fz_t{}_0_0, "
                       "fz_t{}_0_1, fz_t{}_0_2)));\n",
                       indent, g.z_out, g.z_out, g.z_out);
    out += fmt::format("{}float fz_keep = fz_dr / max(fz_next, FG_TINY);\n", indent);
    for (int j = 0; j < 3; ++j) out += fmt::format("{}fz_j{} = fz_t{}_0_{} * fz_keep;\n", indent, j, g.z_out, j);
    out += fmt::format("{}fz_dr = fz_next;\n", indent);
    return out;
}

std::string iteration(const FormulaProgram& prog, const FormulaGroupProgram& g, const std::string& indent) {
    std::string out = prog.jacobian ? jacobian_iteration(prog, g, indent) : scalar_iteration(prog, g, indent);
    out += fmt::format("{}fz_r2_last = fz_r2;\n", indent);
    out += fmt::format("{}fz_r2 = dot(fz_z, fz_z);\n", indent);
    out += fmt::format("{}trap = min(trap, vec4(abs(fz_z.x), abs(fz_z.y), abs(fz_z.z), fz_r2));\n", indent);
    return out;
}

}  // namespace

std::string formula_param_input(const std::string& param) { return "u_" + param; }

std::string formula_glsl(const FormulaProgram& prog) {
    std::string out;
    if (prog.orbit == ValueType::Vec4) {  // a quaternion orbit starts at (p, w): the slice at w
        out += "vec4 fz_z = vec4(p, w);\n";
        out += prog.julia ? "vec4 fz_c = c;\n" : "vec4 fz_c = fz_z;\n";
    } else {
        out += "vec3 fz_z = p;\n";
        out += prog.julia ? "vec3 fz_c = c.xyz;\n" : "vec3 fz_c = p;\n";
    }
    out += "float fz_dr = 1.0;\n";
    if (prog.jacobian) {  // dz/dp starts as the identity (a 4D orbit's w does not move with p)
        const std::string t(type_name(prog.orbit)), w = prog.orbit == ValueType::Vec4 ? ", 0.0" : "";
        out += fmt::format("{} fz_j0 = {}(1.0, 0.0, 0.0{}), fz_j1 = {}(0.0, 1.0, 0.0{}), fz_j2 = {}(0.0, 0.0, 1.0{});\n", t, t,
                           w, t, w, t, w);
    }
    out += "float fz_r2 = dot(fz_z, fz_z);\n";
    out += "float fz_r2_last = fz_r2;\n";
    out += "float fz_bail2 = bailout * bailout;\n";
    out += "trap = vec4(abs(fz_z.x), abs(fz_z.y), abs(fz_z.z), fz_r2);\n";
    out += "int fz_i = 0;\n";
    std::string indent = prog.repeat ? "    " : "";
    if (prog.repeat) out += "do {\n";
    for (const auto& seg : prog.segments) {
        const auto& g = prog.groups[static_cast<std::size_t>(seg.group)];
        out += fmt::format("{}// {}{}\n", indent, g.name,
                           seg.count ? fmt::format(" for {} iteration{}", seg.count, seg.count > 1 ? "s" : "")
                                     : " for every iteration left");
        if (seg.count)
            out += fmt::format("{}for (int fz_n = 0; fz_n < {} && fz_i < iterations; fz_n++, fz_i++) {{\n", indent, seg.count);
        else
            out += fmt::format("{}for (; fz_i < iterations; fz_i++) {{\n", indent);
        out += indent + "    fg_count_fractal_iteration();\n";
        out += indent + "    if (fz_r2 > fz_bail2) break;\n";
        if (!prog.jacobian) out += indent + "    float fz_dr_in = fz_dr;\n";
        out += iteration(prog, g, indent + "    ");
        out += indent + "}\n";
    }
    if (prog.repeat) out += "} while (fz_i < iterations && fz_r2 <= fz_bail2);\n";
    out += "escape = fg_escape_share(fz_i, iterations, fz_r2_last, fz_r2, fz_bail2);\n";
    out += "float fz_r = sqrt(fz_r2);\n";
    switch (prog.estimate) {
        // dr is 0 where a power map's gain is (a quaternion square at z = 0): the maxes keep both finite.
        case FormulaProgram::Estimate::Linear:
            out += prog.linear_radius == 0.0 ? std::string("distance = fz_r / max(fz_dr, FG_TINY);\n")
                                             : fmt::format("distance = (fz_r - {}) / max(fz_dr, FG_TINY);\n",
                                                           Constant::scalar(ValueType::Float, prog.linear_radius).glsl());
            break;
        case FormulaProgram::Estimate::Log:
            out += "distance = 0.5 * log(max(fz_r, FG_TINY)) * fz_r / max(fz_dr, FG_TINY);\n";
            break;
        case FormulaProgram::Estimate::Box:
            out += "vec3 fz_q = abs(fz_z) - vec3(1.0);\n";
            out += "distance = (length(max(fz_q, vec3(0.0))) + min(max(fz_q.x, max(fz_q.y, fz_q.z)), 0.0)) / max(fz_dr, FG_TINY);\n";
            break;
        case FormulaProgram::Estimate::Sheet:
            // The second term is about |z.z| away from the axis and vanishes on it: the sheets stay thin.
            out += "float fz_rxy = sqrt(fz_z.x * fz_z.x + fz_z.y * fz_z.y);\n";
            out += fmt::format("float fz_seed = max(fz_rxy - {}, abs(fz_rxy * fz_z.z) / max(length(fz_z), FG_TINY));\n",
                               Constant::scalar(ValueType::Float, prog.sheet_radius).glsl());
            out += "distance = fz_seed / max(fz_dr, FG_TINY);\n";
            break;
    }
    // The set filled to the iteration count: what has not escaped by the last iteration is inside,
    // whatever the estimate says of its last point.
    if (prog.filled) out += "if (fz_r2 <= fz_bail2) distance = min(distance, 0.0);\n";
    if (prog.bound_radius > 0.0) {
        // Far away the estimate may grow faster than the true distance; the set lies in the bound's
        // ball, so beyond twice its radius the distance to the ball bounds it. A Julia set's ball
        // grows to |c| where that is larger (z^2 + c: every orbit beyond max(2, |c|) escapes).
        std::string radius = Constant::scalar(ValueType::Float, prog.bound_radius).glsl();
        if (prog.julia) radius = fmt::format("max({}, length({}))", radius, prog.orbit == ValueType::Vec4 ? "c" : "c.xyz");
        out += fmt::format("float fz_ball = {};\n", radius);
        out += "float fz_reach = length(p) - fz_ball;\n";
        out += "if (fz_reach > fz_ball) distance = min(distance, fz_reach);\n";
    }
    return out;
}

}  // namespace fg
