#include "lipschitz_bound.h"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <random>

#include "cpu/cpu_evaluator.h"
#include "lipschitz_rule.h"

namespace fg {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Range {
    double absmax = kInf;   // bound of |value| (norm for vectors)
    double absmin = 0.0;
};

double norm(const CpuValue& v, ValueType t) {
    double s = 0;
    for (int i = 0; i < component_count(t); ++i) s += v.v[i] * v.v[i];
    return std::sqrt(s);
}

class LipschitzAnalysis {
public:
    LipschitzAnalysis(const IrGraph& ir, Diagnostics& diag) : ir_(ir), diag_(diag) {}

    LipschitzResult run() {
        sample_ranges();
        LipschitzResult result;
        L_.assign(ir_.nodes.size(), {});
        for (std::size_t i = 0; i < ir_.nodes.size(); ++i) {
            const auto& n = ir_.nodes[i];
            for (std::size_t o = 0; o < n.def->outputs.size(); ++o) L_[i].push_back(output_bound(i, o));
            result.node_bounds.push_back(L_[i].empty() ? 0.0 : L_[i][0]);
        }
        auto it = ir_.outputs.find("distance");
        if (it == ir_.outputs.end()) return result;
        double bound = lipschitz_of(it->second);
        if (!std::isfinite(bound) || bound <= 0) {
            result.exact = false;
            std::string why = unknown_.empty() ? "" : fmt::format(" (unbounded at node \"{}\")", unknown_);
            if (bound <= 0 && std::isfinite(bound)) {
                // A distance that does not depend on the point at all: nothing to march.
                result.notes.push_back("the distance does not vary with the position");
                bound = 1.0;
            } else {
                result.notes.push_back(fmt::format("the Lipschitz bound of the distance is unknown{}; marching "
                                                   "with step scale 1",
                                                   why));
                diag_.warning(fmt::format("cannot bound how fast the distance changes{}: the march assumes it is a "
                                          "true distance (Lipschitz 1); give custom nodes a \"lipschitz\" rule and "
                                          "keep unbounded maths (pow, normalize, divide by a varying value) out of "
                                          "the distance",
                                          why),
                              it->second.pointer, unknown_);
                bound = 1.0;
            }
        }
        result.bound = bound;
        if (std::abs(bound - 1.0) > 1e-9)
            result.notes.push_back(fmt::format("distance Lipschitz bound {:.4g}: steps scaled by {:.4g}", bound, 1.0 / bound));
        return result;
    }

private:
    const IrGraph& ir_;
    Diagnostics& diag_;
    std::vector<std::vector<double>> L_;
    std::vector<std::vector<Range>> ranges_;   // per node output, for point-independent nodes
    std::string unknown_;                       // first node whose bound came out infinite

    // Ranges of values that do not depend on the point: sample the parameter box (corners, then
    // random points; time over an hour) through the CPU twin.
    void sample_ranges() {
        ranges_.assign(ir_.nodes.size(), {});
        for (std::size_t i = 0; i < ir_.nodes.size(); ++i)
            ranges_[i].assign(ir_.nodes[i].def->outputs.size(), Range{});
        Diagnostics quiet;
        auto ev = CpuEvaluator::create(ir_, quiet);
        if (!ev) return;  // custom code: ranges stay unknown
        std::vector<std::size_t> independent;
        for (std::size_t i = 0; i < ir_.nodes.size(); ++i)
            if (!ir_.nodes[i].position_dependent && !ir_.nodes[i].shade_only) independent.push_back(i);
        if (independent.empty()) return;
        for (auto i : independent)
            for (auto& r : ranges_[i]) r = Range{0.0, kInf};
        std::mt19937 rng(12345);
        const std::size_t params = ir_.params.size();
        const std::size_t corners = params <= 6 ? (std::size_t{1} << params) : 0;
        const std::size_t samples = corners + 64;
        for (std::size_t s = 0; s < samples; ++s) {
            CpuEvaluator e = *ev;
            for (std::size_t k = 0; k < params; ++k) {
                const auto& p = ir_.params[k];
                Constant c = p.value;
                if (p.min && p.max) {
                    // A parameter without a range is sampled at its default only: the bound then
                    // holds for the default, and fgc check says so.
                    double t = s < corners ? static_cast<double>((s >> k) & 1u)
                                           : std::uniform_real_distribution<double>(0.0, 1.0)(rng);
                    for (int comp = 0; comp < component_count(p.type); ++comp)
                        c.v[static_cast<std::size_t>(comp)] = *p.min + t * (*p.max - *p.min);
                    if (p.type == ValueType::Int)
                        c.v[0] = std::round(c.v[0]);
                }
                e.set_param(p.name, c);
            }
            e.set_time(s < corners ? 0.0 : std::uniform_real_distribution<double>(0.0, 3600.0)(rng));
            auto slots = e.evaluate_nodes(glm::dvec3(0.0));
            for (auto i : independent) {
                const auto& n = ir_.nodes[i];
                for (std::size_t o = 0; o < n.def->outputs.size(); ++o) {
                    const auto& v = slots[e.slot(static_cast<int>(i), static_cast<int>(o))];
                    double m = norm(v, n.output_types[o]);
                    auto& r = ranges_[i][o];
                    r.absmax = std::max(r.absmax, m);
                    r.absmin = std::min(r.absmin, m);
                }
            }
        }
        // Sampling can miss extremes between samples: widen by 10 %.
        for (auto i : independent)
            for (auto& r : ranges_[i]) {
                r.absmax *= 1.1;
                r.absmin /= 1.1;
            }
    }

    Range range_of(const IrInput& in) const {
        switch (in.kind) {
            case IrInput::Kind::Constant:
            case IrInput::Kind::Knob: {
                double m = 0;
                for (int i = 0; i < component_count(in.constant.type); ++i)
                    m += in.constant.v[static_cast<std::size_t>(i)] * in.constant.v[static_cast<std::size_t>(i)];
                return {std::sqrt(m), std::sqrt(m)};
            }
            case IrInput::Kind::Param: {
                const auto& p = ir_.params[static_cast<std::size_t>(in.param)];
                if (!p.min || !p.max) return {kInf, 0.0};
                double hi = std::max(std::abs(*p.min), std::abs(*p.max));
                double lo = (*p.min <= 0 && *p.max >= 0) ? 0.0 : std::min(std::abs(*p.min), std::abs(*p.max));
                double k = std::sqrt(static_cast<double>(component_count(p.type)));
                return {hi * k, lo};
            }
            case IrInput::Kind::Implicit:
                if (in.implicit == ImplicitSource::Position)
                    return {glm::length(ir_.scene.bounds_center) + ir_.scene.bounds_radius, 0.0};
                if (in.implicit == ImplicitSource::Time) return {kInf, 0.0};
                return {1.0, 1.0};  // unit directions
            case IrInput::Kind::Node:
                return ranges_[static_cast<std::size_t>(in.node)][static_cast<std::size_t>(in.port)];
        }
        return {};
    }

    double lipschitz_of(const IrInput& in) const {
        switch (in.kind) {
            case IrInput::Kind::Implicit: return in.implicit == ImplicitSource::Position ? 1.0 : 0.0;
            case IrInput::Kind::Node: return L_[static_cast<std::size_t>(in.node)][static_cast<std::size_t>(in.port)];
            default: return 0.0;
        }
    }

    double output_bound(std::size_t node, std::size_t port) {
        const IrNode& n = ir_.nodes[node];
        if (!n.position_dependent) return 0.0;
        const auto& out = n.def->outputs[port];
        auto rule_it = n.def->lipschitz.find(out.name);
        if (rule_it == n.def->lipschitz.end()) {
            if (unknown_.empty()) unknown_ = n.id;
            return kInf;
        }
        std::string error;
        auto rule = LipschitzRule::parse(rule_it->second, error);
        if (!rule) {
            diag_.error(fmt::format("Lipschitz rule \"{}\" of {}: {}", rule_it->second, n.def->type, error), n.pointer,
                        n.id);
            return kInf;
        }
        LipschitzEnv env;
        auto input = [&](const std::string& port_name) -> const IrInput* {
            for (std::size_t i = 0; i < n.def->inputs.size(); ++i)
                if (n.def->inputs[i].name == port_name) return &n.inputs[i];
            return nullptr;
        };
        env.lipschitz = [&](const std::string& p) {
            const IrInput* in = input(p);
            return in ? lipschitz_of(*in) : kInf;
        };
        env.absmax = [&](const std::string& p) {
            const IrInput* in = input(p);
            return in ? range_of(*in).absmax : kInf;
        };
        env.absmin = [&](const std::string& p) {
            const IrInput* in = input(p);
            return in ? range_of(*in).absmin : 0.0;
        };
        env.bounds_radius = ir_.scene.bounds_radius;
        double L = rule->evaluate(env);
        if (std::isnan(L)) L = kInf;
        if (!std::isfinite(L) && unknown_.empty()) unknown_ = n.id;
        return L;
    }
};

}  // namespace

LipschitzResult analyse_lipschitz(const IrGraph& ir, Diagnostics& diag) { return LipschitzAnalysis(ir, diag).run(); }

}  // namespace fg
