// Formulas with maths nodes carry a running Jacobian: every node's tangent rule is what a central
// finite difference measures; a box fold drawn in maths nodes is the box fold stage; the carried
// derivative bounds the largest stretch of the iterated map, and equals it for similarities; a
// body's mistakes are errors at their JSON pointer; and such a formula compiles to valid SPIR-V.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cpu/cpu_evaluator.h"
#include "cpu/cpu_node_registry.h"
#include "test_support.h"

using namespace fg;
using fg::test::has_error;
using nlohmann::json;

namespace {

// A node run at inputs `in`; tangents of the rule's outputs for tangents `d` of its inputs.
struct TangentCall {
    const NodeDefinition* def;
    std::optional<ValueType> generic;
    CpuNodeFunction value;
    CpuTangentFunction tangent;
    std::vector<int> inputs, outputs;  // the rule's ports, as indices

    TangentCall(const NodeDefinition* d, std::optional<ValueType> t)
        : def(d), generic(t), value(find_cpu_node(d->type, t)), tangent(find_cpu_tangent(d->type, t)) {
        for (const auto& name : d->tangent.inputs) inputs.push_back(static_cast<int>(d->find_input(name) - d->inputs.data()));
        for (const auto& name : d->tangent.outputs) outputs.push_back(static_cast<int>(d->find_output(name) - d->outputs.data()));
    }
    ValueType type(const PortType& p) const { return p.concrete ? *p.concrete : generic.value_or(ValueType::Vec3); }
    std::vector<glm::dvec4> outputs_at(std::vector<CpuValue> in) const {
        std::vector<CpuValue> out(def->outputs.size());
        value(in.data(), out.data());
        std::vector<glm::dvec4> v;
        for (int o : outputs) v.push_back(out[static_cast<std::size_t>(o)].v);
        return v;
    }
    // Central difference of the rule's outputs along `d` with step h.
    std::vector<glm::dvec4> difference(const std::vector<CpuValue>& in, const std::vector<CpuValue>& d, double h) const {
        std::vector<CpuValue> plus = in, minus = in;
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            plus[static_cast<std::size_t>(inputs[k])].v += h * d[k].v;
            minus[static_cast<std::size_t>(inputs[k])].v -= h * d[k].v;
        }
        auto a = outputs_at(plus), b = outputs_at(minus);
        for (std::size_t k = 0; k < a.size(); ++k) a[k] = (a[k] - b[k]) / (2.0 * h);
        return a;
    }
};

glm::dvec4 random_value(ValueType t, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    glm::dvec4 v(0.0);
    for (int i = 0; i < component_count(t); ++i) v[i] = u(rng);
    return v;
}

double largest(const glm::dvec4& v) { return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::max(std::abs(v.z), std::abs(v.w))); }

TEST(Jacobian, every_tangent_rule_is_what_a_finite_difference_measures) {
    std::mt19937_64 rng(5);
    int rules = 0;
    for (const auto* def : NodeLibrary::builtin().all()) {
        if (def->tangent.empty()) continue;
        std::vector<std::optional<ValueType>> instances;
        if (def->generic.empty()) instances.push_back(std::nullopt);
        for (auto t : def->generic) instances.push_back(t);
        for (auto t : instances) {
            SCOPED_TRACE(def->type + (t ? " " + std::string(type_name(*t)) : ""));
            TangentCall call(def, t);
            ASSERT_TRUE(call.value && call.tangent);
            ++rules;
            int checked = 0;
            for (int i = 0; i < 400 && checked < 60; ++i) {
                // The rule's inputs anywhere; the others at their example's values or defaults.
                std::vector<CpuValue> in;
                const json example = def->example.value("inputs", json::object());
                for (const auto& port : def->inputs) {
                    Constant v = port.default_value.value_or(Constant{});
                    if (example.contains(port.name) && example[port.name].is_number())
                        v = Constant::scalar(call.type(port.type), example[port.name].get<double>());
                    in.push_back(CpuValue::of(v));
                }
                std::vector<CpuValue> d;
                for (int k : call.inputs) {
                    const ValueType type = call.type(def->inputs[static_cast<std::size_t>(k)].type);
                    in[static_cast<std::size_t>(k)].v = random_value(type, rng);
                    d.push_back(CpuValue::of(random_value(type, rng)));
                }
                if (def->find_input("lo") && def->find_input("hi")) {  // a clamp's range the right way round
                    auto &lo = in[1].v.x, &hi = in[2].v.x;
                    if (lo > hi) std::swap(lo, hi);
                }
                // Kinks (folds, clamps, min and max) where two step sizes disagree are skipped.
                auto fd = call.difference(in, d, 1e-5), fd2 = call.difference(in, d, 5e-6);
                bool smooth = true;
                for (std::size_t k = 0; k < fd.size(); ++k) smooth &= largest(fd[k] - fd2[k]) <= 1e-4 * std::max(1.0, largest(fd[k]));
                if (!smooth) continue;
                // Richardson's extrapolation of the two: exact to h^4, so steep places (near a pole) pass too.
                for (std::size_t k = 0; k < fd.size(); ++k) fd[k] = (4.0 * fd2[k] - fd[k]) / 3.0;
                ++checked;
                std::vector<CpuValue> out(call.outputs.size());
                call.tangent(in.data(), d.data(), out.data());
                for (std::size_t k = 0; k < fd.size(); ++k)
                    EXPECT_LE(largest(out[k].v - fd[k]), 1e-6 * std::max(1.0, largest(fd[k])))
                        << def->tangent.outputs[k] << " at input " << in[0].v.x << " " << in[0].v.y << " " << in[0].v.z;
            }
            EXPECT_GE(checked, 30) << "too few points away from the node's kinks";
        }
    }
    EXPECT_GE(rules, 60);
}

// A graph's CPU twin, with the IR it reads.
struct Twin {
    std::unique_ptr<IrGraph> ir;
    std::optional<CpuEvaluator> ev;
    explicit operator bool() const { return ev.has_value(); }
    double distance(glm::dvec3 p) { return ev->distance(p); }
};

Twin evaluator(const json& graph) {
    Diagnostics diag;
    Twin twin;
    auto ir = load_and_lower(graph.dump(), NodeLibrary::builtin(), diag);
    EXPECT_TRUE(ir) << diag.format();
    if (!ir) return twin;
    twin.ir = std::make_unique<IrGraph>(std::move(*ir));
    twin.ev = CpuEvaluator::create(*twin.ir, diag);
    EXPECT_TRUE(twin.ev) << diag.format();
    return twin;
}

json graph_file(const std::string& relative) { return json::parse(fg::test::read_source_file(relative)); }

json with_jacobian(json graph) {
    graph["nodes"][0]["formula"]["derivative"] = "jacobian";
    return graph;
}

double largest_relative_difference(const json& a, const json& b, double radius, int points) {
    auto ea = evaluator(a), eb = evaluator(b);
    if (!ea || !eb) return 1e30;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-radius, radius);
    double worst = 0.0;
    for (int i = 0; i < points; ++i) {
        glm::dvec3 p(u(rng), u(rng), u(rng));
        double da = ea.distance(p), db = eb.distance(p);
        worst = std::max(worst, std::abs(da - db) / std::max(std::abs(da), 1e-12));
    }
    return worst;
}

TEST(Jacobian, a_box_fold_drawn_in_maths_nodes_is_the_box_fold_stage) {
    EXPECT_LT(largest_relative_difference(graph_file("graphs/formulas/mandelbox_maths.json"),
                                          with_jacobian(graph_file("graphs/formulas/mandelbox.json")), 4.0, 20000),
              1e-12);
}

TEST(Jacobian, for_similarities_the_running_jacobian_is_the_scalar_derivative) {
    // Folds, turns and uniform scales only: dz/dp is a rotation times dr, whose norm is dr.
    const json sponge = graph_file("graphs/formulas/menger_twisted.json");
    EXPECT_LT(largest_relative_difference(sponge, with_jacobian(sponge), 1.5, 20000), 1e-9);
    const json kleinian = graph_file("graphs/formulas/kleinian.json");
    EXPECT_LT(largest_relative_difference(kleinian, with_jacobian(kleinian), 4.0, 20000), 1e-9);
}

// Three iterations of z -> twist(z) * 2 + c, written here independently of the graph.
glm::dvec3 twisted_orbit(glm::dvec3 p, double rate) {
    glm::dvec3 z = p;
    for (int i = 0; i < 3; ++i) {
        double a = rate * z.y, c = std::cos(a), s = std::sin(a);
        z = glm::dvec3(z.x * c - z.z * s, z.y, z.x * s + z.z * c) * 2.0 + p;
    }
    return z;
}

TEST(Jacobian, the_carried_derivative_bounds_the_largest_stretch_of_the_iterated_map) {
    json g = fg::test::minimal_graph();
    g["nodes"][0] = json::parse(R"({"id": "f", "type": "fractal.formula", "inputs": {"iterations": 3, "bailout": 1e6, "bias": 0.0},
      "formula": {"groups": [{"name": "twist", "nodes": [
        {"id": "orbit", "type": "stage.orbit"},
        {"id": "parts", "type": "math.split", "inputs": {"v": "orbit.z"}},
        {"id": "angle", "type": "math.scale", "inputs": {"v": "parts.y", "s": 0.7}},
        {"id": "cos", "type": "math.cos", "inputs": {"x": "angle"}},
        {"id": "sin", "type": "math.sin", "inputs": {"x": "angle"}},
        {"id": "xc", "type": "math.multiply", "inputs": {"a": "parts.x", "b": "cos"}},
        {"id": "zs", "type": "math.multiply", "inputs": {"a": "parts.z", "b": "sin"}},
        {"id": "xs", "type": "math.multiply", "inputs": {"a": "parts.x", "b": "sin"}},
        {"id": "zc", "type": "math.multiply", "inputs": {"a": "parts.z", "b": "cos"}},
        {"id": "x", "type": "math.subtract", "inputs": {"a": "xc", "b": "zs"}},
        {"id": "z", "type": "math.add", "inputs": {"a": "xs", "b": "zc"}},
        {"id": "turned", "type": "math.vec3", "inputs": {"x": "x", "y": "parts.y", "z": "z"}},
        {"id": "double", "type": "stage.scale", "inputs": {"z": "turned", "scale": 2.0}},
        {"id": "add", "type": "math.add", "inputs": {"a": "double", "b": "orbit.c"}}]}]}})");
    g["outputs"]["distance"] = "f.distance";
    auto ev = evaluator(g);
    ASSERT_TRUE(ev);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-0.6, 0.6);
    for (int i = 0; i < 200; ++i) {
        glm::dvec3 p(u(rng), u(rng), u(rng));
        // The linear estimate without a guard is |z| / dr: dr is what the formula carried.
        const glm::dvec3 z = twisted_orbit(p, 0.7);
        const double dr = glm::length(z) / ev.distance(p);
        glm::dmat3 j;
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 e(0.0);
            e[a] = 1e-6;
            j[a] = (twisted_orbit(p + e, 0.7) - twisted_orbit(p - e, 0.7)) / 2e-6;
        }
        // The largest singular value, by power iteration on J^T J.
        glm::dmat3 m = glm::transpose(j) * j;
        glm::dvec3 v(1.0, 0.7, 0.3);
        for (int k = 0; k < 200; ++k) v = glm::normalize(m * v);
        const double stretch = std::sqrt(glm::length(m * v));
        EXPECT_GE(dr, stretch * (1.0 - 1e-6)) << "never below the true stretch";
        EXPECT_LE(dr, stretch * std::sqrt(3.0) * (1.0 + 1e-6)) << "the bound stays within sqrt(3) of it";
    }
}

TEST(Jacobian, mistakes_in_a_maths_body_are_errors_at_their_pointer) {
    const std::string at = "/nodes/0/formula";
    // A node that has no tangent rule: a jump has no derivative to carry.
    auto diag = fg::test::check_front(fg::test::formula_graph(json::parse(R"({"groups": [{"name": "a", "nodes": [
        {"id": "o", "type": "stage.orbit"}, {"id": "f", "type": "math.floor", "inputs": {"x": "o.z"}}]}]})")));
    EXPECT_TRUE(has_error(diag, at + "/groups/0/nodes/1/type", "f", "maths nodes with a tangent rule"));

    // An input its tangent rule holds constant, fed the orbit; a stage's gain, which has no tangent.
    diag = fg::test::check_front(fg::test::formula_graph(json::parse(R"({"groups": [{"name": "a", "nodes": [
        {"id": "o", "type": "stage.orbit"},
        {"id": "parts", "type": "math.split", "inputs": {"v": "o.z"}},
        {"id": "soft", "type": "math.smoothstep", "inputs": {"edge0": "parts.x", "x": "o.z"}},
        {"id": "sphere", "type": "stage.sphere_fold", "inputs": {"z": "soft"}},
        {"id": "grow", "type": "math.scale", "inputs": {"v": "sphere", "s": "sphere.gain"}}]}]})")));
    EXPECT_TRUE(has_error(diag, at + "/groups/0/nodes/2/inputs/edge0", "f", "holds that input constant"));
    EXPECT_TRUE(has_error(diag, at + "/groups/0/nodes/4/inputs/s", "f", "has no tangent rule"));

    // Operands of two types; a group leaving with a number; maths under a scalar derivative.
    diag = fg::test::check_front(fg::test::formula_graph(json::parse(R"({"derivative": "scalar", "groups": [{"name": "a", "nodes": [
        {"id": "o", "type": "stage.orbit"},
        {"id": "parts", "type": "math.split", "inputs": {"v": "o.z"}},
        {"id": "sum", "type": "math.add", "inputs": {"a": "o.z", "b": "parts.x"}},
        {"id": "size", "type": "math.length", "inputs": {"v": "sum"}}]}]})")));
    EXPECT_TRUE(has_error(diag, at + "/groups/0/nodes/2/inputs/b", "f", "must be the same type"));
    EXPECT_TRUE(has_error(diag, at + "/groups/0/z", "f", "whose first output is float"));
    EXPECT_TRUE(has_error(diag, at + "/derivative", "f", "needs the running Jacobian"));
}

TEST(Jacobian, a_formula_with_maths_nodes_compiles_to_valid_spirv) {
    Diagnostics diag;
    auto result = fg::test::compile_text(fg::test::read_source_file("graphs/formulas/twisted_box.json"), diag);
    ASSERT_TRUE(result) << diag.format();
    EXPECT_FALSE(diag.has_errors()) << diag.format();
    bool tangents = false;
    for (const auto& pass : result->passes) tangents |= pass.source.glsl.find("fg_math_multiply_tangent(") != std::string::npos;
    EXPECT_TRUE(tangents);
}

}  // namespace
