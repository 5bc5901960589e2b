// Formulas drawn as graphs: every stage's declared derivative is what a central finite difference
// measures; the gallery Mandelbox and Mandelbulb written as formula graphs give the hand-written
// nodes' distances on the CPU twin and compile through glslang and SPIR-V validation; a hybrid
// runs its schedule; and a body's mistakes are errors at their JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <fmt/format.h>

#include "cpu/cpu_evaluator.h"
#include "cpu/cpu_node_registry.h"
#include "test_support.h"

using namespace fg;
using fg::test::has_error;
using nlohmann::json;

namespace {

using Rule = StageDerivative::Rule;

std::vector<const NodeDefinition*> stages() {
    std::vector<const NodeDefinition*> out;
    for (const auto* d : NodeLibrary::builtin().all())
        if (d->is_stage() && d->derivative.rule != Rule::Orbit) out.push_back(d);
    return out;
}

// A stage run on z with its example's literals (defaults elsewhere); c is a fixed point. Generic
// stages run as their vec3 instance; quaternion stages on 4D points.
struct StageCall {
    const NodeDefinition* def;
    std::vector<CpuValue> in;
    CpuNodeFunction fn;
    int n;   // the orbit's dimension

    explicit StageCall(const NodeDefinition* d)
        : def(d),
          fn(find_cpu_node(d->type, d->generic.empty() ? std::nullopt : std::optional<ValueType>(ValueType::Vec3))),
          n(d->inputs[0].type.concrete == ValueType::Vec4 ? 4 : 3) {
        const json example = d->example.value("inputs", json::object());
        for (const auto& port : d->inputs) {
            Constant v = port.default_value.value_or(Constant{});
            if (example.contains(port.name) && example[port.name].is_number())
                v = Constant::scalar(ValueType::Float, example[port.name].get<double>());
            if (example.contains(port.name) && example[port.name].is_array()) {
                std::array<double, 4> xs{};
                for (std::size_t i = 0; i < example[port.name].size(); ++i) xs[i] = example[port.name][i].get<double>();
                v = Constant::vector(port.type.concrete.value_or(ValueType::Vec3), xs);
            }
            in.push_back(CpuValue::of(v));
        }
        if (auto* c = d->find_input("c")) in[static_cast<std::size_t>(c - d->inputs.data())] = CpuValue::of(glm::dvec4(0.3, -0.2, 0.1, 0.0));
    }
    std::vector<CpuValue> operator()(const glm::dvec4& z) {
        in[0] = CpuValue::of(z);
        std::vector<CpuValue> out(def->outputs.size());
        fn(in.data(), out.data());
        return out;
    }
    int factor_output() const {
        for (std::size_t k = 0; k < def->outputs.size(); ++k)
            if (def->outputs[k].name == def->derivative.factor) return static_cast<int>(k);
        return -1;
    }
};

// The Jacobian of the stage at z by central differences with step h (n x n; the rest zero).
glm::dmat4 jacobian(StageCall& call, const glm::dvec4& z, double h) {
    glm::dmat4 j(0.0);
    for (int a = 0; a < call.n; ++a) {
        glm::dvec4 e(0.0);
        e[a] = h;
        j[a] = (call(z + e)[0].v4() - call(z - e)[0].v4()) / (2.0 * h);
    }
    return j;
}

double max_abs(const glm::dmat4& m, int n) {
    double x = 0.0;
    for (int c = 0; c < n; ++c)
        for (int r = 0; r < n; ++r) x = std::max(x, std::abs(m[c][r]));
    return x;
}

glm::dmat4 identity(int n) {
    glm::dmat4 m(0.0);
    for (int i = 0; i < n; ++i) m[i][i] = 1.0;
    return m;
}

TEST(Formula, every_stage_declares_a_derivative_a_finite_difference_confirms) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    ASSERT_GE(stages().size(), 12u);
    for (const auto* def : stages()) {
        SCOPED_TRACE(def->type);
        StageCall call(def);
        ASSERT_NE(call.fn, nullptr);
        const int n = call.n;
        int checked = 0;
        for (int i = 0; i < 400 && checked < 100; ++i) {
            glm::dvec4 z(u(rng), u(rng), u(rng), n == 4 ? u(rng) : 0.0);
            // A fold's pieces meet along kinks: where two step sizes disagree the point is on one.
            glm::dmat4 j = jacobian(call, z, 1e-5), j2 = jacobian(call, z, 5e-6);
            if (max_abs(j - j2, n) > 1e-7 * std::max(1.0, max_abs(j, n))) continue;
            ++checked;
            auto out = call(z);
            switch (def->derivative.rule) {
                case Rule::Isometry:
                case Rule::AddC: {
                    // Lengths kept: J^T J = I (for add_c, the derivative in z; c adds |weight| in p).
                    EXPECT_LT(max_abs(glm::transpose(j) * j - identity(n), n), 1e-6) << z.x << " " << z.y << " " << z.z;
                    break;
                }
                case Rule::Conformal: {
                    // Locally a similarity with the declared factor k: J^T J = k^2 I.
                    double k = out[static_cast<std::size_t>(call.factor_output())].f();
                    EXPECT_LT(max_abs(glm::transpose(j) * j / (k * k) - identity(n), n), 1e-6)
                        << z.x << " " << z.y << " " << z.z << " k " << k;
                    break;
                }
                case Rule::Bound: {
                    // A norm bound: no direction stretches more than the declared factor, and one does by it.
                    double bound = out[static_cast<std::size_t>(call.factor_output())].f();
                    double largest = 0.0;
                    for (int a = 0; a < n; ++a) {
                        glm::dvec4 e(0.0);
                        e[a] = 1.0;
                        largest = std::max(largest, glm::length(j * e));
                    }
                    for (int t = 0; t < 20; ++t) {
                        glm::dvec4 v(u(rng), u(rng), u(rng), n == 4 ? u(rng) : 0.0);
                        EXPECT_LE(glm::length(j * v), bound * glm::length(v) * (1.0 + 1e-6));
                    }
                    EXPECT_NEAR(largest / bound, 1.0, 1e-6) << "the bound is the largest stretch, not more";
                    break;
                }
                case Rule::Power: {
                    // A power map: the declared gain is the radial stretch |J r^| (it is not conformal).
                    double gain = out[static_cast<std::size_t>(call.factor_output())].f();
                    double radial = glm::length(j * glm::normalize(z));
                    EXPECT_NEAR(radial / gain, 1.0, 1e-6) << z.x << " " << z.y << " " << z.z;
                    break;
                }
                case Rule::None: ADD_FAILURE(); break;
            }
        }
        EXPECT_GE(checked, 50) << "too few points away from the stage's kinks";
    }
}

std::optional<IrGraph> lower(const json& graph, Diagnostics& diag) {
    return load_and_lower(graph.dump(), NodeLibrary::builtin(), diag);
}

json graph_file(const std::string& relative) { return json::parse(fg::test::read_source_file(relative)); }

// Distances of two graphs at random points of a ball, on the CPU twin: the largest relative difference.
double largest_relative_difference(const std::string& a, const std::string& b, double radius, int points) {
    Diagnostics diag;
    auto ia = lower(graph_file(a), diag), ib = lower(graph_file(b), diag);
    EXPECT_TRUE(ia && ib) << diag.format();
    if (!ia || !ib) return 1e30;
    auto ea = CpuEvaluator::create(*ia, diag), eb = CpuEvaluator::create(*ib, diag);
    EXPECT_TRUE(ea && eb) << diag.format();
    if (!ea || !eb) return 1e30;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-radius, radius);
    double worst = 0.0;
    for (int i = 0; i < points; ++i) {
        glm::dvec3 p(u(rng), u(rng), u(rng));
        double da = ea->distance(p), db = eb->distance(p);
        worst = std::max(worst, std::abs(da - db) / std::max(std::abs(da), 1e-12));
    }
    return worst;
}

TEST(Formula, the_gallery_mandelbox_as_a_formula_graph_is_the_mandelbox_node) {
    // Not bit for bit: the hand-written node scales by k * scale in one product, the formula by k
    // and then by scale, and a last-bit difference grows over 12 iterations (6e-11 at most).
    EXPECT_LT(largest_relative_difference("graphs/gallery/mandelbox.json", "graphs/formulas/mandelbox.json", 4.0, 100000),
              1e-9);
}

TEST(Formula, the_gallery_mandelbulb_as_a_formula_graph_is_the_mandelbulb_node) {
    EXPECT_LT(largest_relative_difference("graphs/gallery/mandelbulb.json", "graphs/formulas/mandelbulb.json", 1.3, 100000),
              1e-12);
}

TEST(Formula, the_gallery_twisted_sponge_as_a_formula_graph_is_the_menger_node) {
    EXPECT_LT(largest_relative_difference("graphs/gallery/menger_twisted.json", "graphs/formulas/menger_twisted.json", 1.5,
                                          100000),
              1e-12);
}

TEST(Formula, the_gallery_julia_as_a_formula_graph_is_the_julia_node) {
    EXPECT_LT(largest_relative_difference("graphs/gallery/julia.json", "graphs/formulas/julia.json", 1.6, 100000), 1e-12);
}

TEST(Formula, the_gallery_kleinian_as_a_formula_graph_is_the_kleinian_node) {
    // The hand-written node has no bailout; the formula's 1e6 is never reached by these bounded orbits.
    EXPECT_LT(largest_relative_difference("graphs/gallery/kleinian.json", "graphs/formulas/kleinian.json", 4.0, 100000),
              1e-12);
}

TEST(Formula, the_compiler_derives_the_estimate_and_guards_the_derivative_in_the_pass) {
    Diagnostics diag;
    auto bulb = fg::test::compile_text(graph_file("graphs/formulas/mandelbulb.json").dump(), diag);
    ASSERT_TRUE(bulb) << diag.format();
    EXPECT_FALSE(diag.has_errors()) << diag.format();
    const IrNode& node = bulb->ir.nodes[static_cast<std::size_t>(bulb->ir.find("bulb"))];
    ASSERT_TRUE(node.formula);
    EXPECT_EQ(node.formula->estimate, FormulaProgram::Estimate::Log);
    EXPECT_NE(node.def->running_derivative.find("power map"), std::string::npos) << node.def->running_derivative;
    bool guarded = false, stage_called = false;
    for (const auto& pass : bulb->passes) {
        guarded |= pass.source.glsl.find("fg_conservative_dr(fz_dr, bias,") != std::string::npos;
        stage_called |= pass.source.glsl.find("fg_stage_triplex_power(") != std::string::npos;
    }
    EXPECT_TRUE(guarded && stage_called);
    // The bias is a knob calibrate can set, as on a hand-written fractal.
    bool knob = false;
    for (const auto& f : bulb->manifest.fractals) knob |= f.node == "bulb" && f.bias_spec != 0;
    EXPECT_TRUE(knob);

    auto box = load_and_lower(graph_file("graphs/formulas/mandelbox.json").dump(), NodeLibrary::builtin(), diag);
    ASSERT_TRUE(box) << diag.format();
    EXPECT_EQ(box->nodes[static_cast<std::size_t>(box->find("box"))].formula->estimate, FormulaProgram::Estimate::Linear);
}

TEST(Formula, a_hybrid_runs_its_schedule_and_compiles) {
    Diagnostics diag;
    const json hybrid = graph_file("graphs/gallery/bulb_box_hybrid.json");
    auto result = fg::test::compile_text(hybrid.dump(), diag);
    ASSERT_TRUE(result) << diag.format();
    auto ev = CpuEvaluator::create(result->ir, diag);
    ASSERT_TRUE(ev) << diag.format();
    // Two bulb iterations then the box: at a point where the two orders differ, the distance is the
    // one of that schedule and not of the groups the other way round.
    json swapped = hybrid;
    swapped["nodes"][0]["formula"]["schedule"] = json::parse(R"([{"group": "box", "count": 2}, {"group": "bulb"}])");
    auto other = load_and_lower(swapped.dump(), NodeLibrary::builtin(), diag);
    ASSERT_TRUE(other) << diag.format();
    auto ev_other = CpuEvaluator::create(*other, diag);
    ASSERT_TRUE(ev_other);
    int differ = 0;
    for (double x = -2.0; x <= 2.0; x += 0.25) differ += std::abs(ev->distance({x, 0.3, 0.2}) - ev_other->distance({x, 0.3, 0.2})) > 1e-6;
    EXPECT_GT(differ, 8);
    for (double x = -6.0; x <= 6.0; x += 0.5) EXPECT_TRUE(std::isfinite(ev->distance({x, 0.1, -0.2}))) << x;
}

TEST(Formula, the_escape_output_counts_the_iterations_to_the_bailout_in_log_steps) {
    // z -> 2z from |p| = r reaches |z| = 2^n r: it passes the bailout B after log2(B / r)
    // iterations, which the escape output gives exactly (the last one counted in log |z|), capped
    // at the maximum where the orbit stays inside, and 0 where it starts outside.
    const double bailout = 100.0;
    const int iterations = 12;
    json g = fg::test::minimal_graph();
    g["nodes"][0] = json::parse(fmt::format(R"({{"id": "f", "type": "fractal.formula",
        "inputs": {{"iterations": {}, "bailout": {}, "bias": 0.0}},
        "formula": {{"groups": [{{"name": "double", "nodes": [{{"id": "s", "type": "stage.scale", "inputs": {{"scale": 2.0}}}}]}}]}}}})",
                                            iterations, bailout));
    g["outputs"] = {{"distance", "f.distance"}, {"ao", "f.escape"}};
    Diagnostics diag;
    auto ir = lower(g, diag);
    ASSERT_TRUE(ir) << diag.format();
    auto ev = CpuEvaluator::create(*ir, diag);
    ASSERT_TRUE(ev) << diag.format();
    for (double r : {0.05, 0.3, 1.0, 2.5, 7.0, 60.0, 99.0, 150.0}) {
        const glm::dvec3 p = r * glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
        const double expected = r > bailout ? 0.0 : std::min(std::log2(bailout / r), double(iterations));
        EXPECT_NEAR(ev->output("ao", p, {})->f(), expected, 1e-9) << "|p| = " << r;
    }
}

TEST(Formula, mistakes_in_a_body_are_errors_at_their_pointer) {
    // A stage outside a formula.
    json g = fg::test::minimal_graph();
    g["nodes"][0] = {{"id", "ball"}, {"type", "stage.box_fold"}};
    EXPECT_TRUE(has_error(fg::test::check_front(g), "/nodes/0/type", "ball", "works only inside the body"));

    // A node that is not a stage inside a body.
    auto body = json::parse(R"({"groups": [{"name": "g", "nodes": [{"id": "s", "type": "prim.sphere"}]}]})");
    EXPECT_TRUE(has_error(fg::test::check_front(fg::test::formula_graph(body)), "/nodes/0/formula/groups/0/nodes/0/type", "f",
                          "holds stage.* nodes"));

    // A schedule naming no group, and a segment without a count before the last.
    body = json::parse(R"({"groups": [{"name": "a", "nodes": [{"id": "s", "type": "stage.abs_fold"}]},
                                      {"name": "b", "nodes": [{"id": "t", "type": "stage.scale"}]}],
                           "schedule": [{"group": "a"}, {"group": "c", "count": 2}]})");
    auto diag = fg::test::check_front(fg::test::formula_graph(body));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/schedule/1/group", "f", "no group \"c\""));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/schedule/0", "f", "only the last segment"));

    // z from a stage of another group; a parameter taken from a stage's output.
    body = json::parse(R"({"groups": [{"name": "a", "nodes": [{"id": "s", "type": "stage.abs_fold"}]},
                                      {"name": "b", "nodes": [{"id": "t", "type": "stage.scale", "inputs": {"z": "s", "scale": "s.z"}}]}],
                           "schedule": [{"group": "a", "count": 1}, {"group": "b"}]})");
    diag = fg::test::check_front(fg::test::formula_graph(body));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/1/nodes/0/inputs/z", "f", "not a node of this group"));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/1/nodes/0/inputs/scale", "f", "not a node of this group"));

    // A stage's parameter taken from the orbit: a stage's derivative rule covers only its z.
    body = json::parse(R"({"derivative": "scalar", "groups": [{"name": "a", "nodes": [{"id": "s", "type": "stage.abs_fold"},
        {"id": "t", "type": "stage.translate", "inputs": {"z": "s", "offset": "s"}}]}]})");
    diag = fg::test::check_front(fg::test::formula_graph(body));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/0/nodes/1/inputs/offset", "f", "covers only its z"));

    // A cycle through z, and an unknown parameter.
    body = json::parse(R"({"groups": [{"name": "a", "nodes": [
        {"id": "s", "type": "stage.abs_fold", "inputs": {"z": "t"}},
        {"id": "t", "type": "stage.scale", "inputs": {"z": "s", "scale": "$nope"}}]}]})");
    diag = fg::test::check_front(fg::test::formula_graph(body));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/0/nodes/1/inputs/z", "f", "cycle"));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/0/nodes/1/inputs/scale", "f", "unknown parameter \"$nope\""));

    // A parameter of the wrong type for the stage's port (a float one is broadcast to a vector port).
    g = fg::test::formula_graph(json::parse(R"({"groups": [{"name": "a", "nodes": [
        {"id": "s", "type": "stage.scale", "inputs": {"scale": "$corner"}},
        {"id": "t", "type": "stage.translate", "inputs": {"z": "s", "offset": "$radius"}}]}]})"));
    g["params"]["corner"] = {{"type", "vec3"}, {"default", {1.0, 1.0, 1.0}}};
    diag = fg::test::check_front(g);
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/0/nodes/0/inputs/scale", "f", "type mismatch"));
    EXPECT_EQ(diag.error_count(), 1u) << diag.format();

    // 3D and quaternion stages in one orbit; a cube seed for a 4D orbit.
    g = fg::test::formula_graph(json::parse(R"({"estimate": "box", "groups": [{"name": "a", "nodes": [
        {"id": "s", "type": "stage.abs_fold"}, {"id": "q", "type": "stage.quaternion_square"}]}]})"));
    diag = fg::test::check_front(g);
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/groups/0/nodes/1/type", "f", "one kind of orbit"));
    EXPECT_TRUE(has_error(diag, "/nodes/0/formula/estimate", "f", "a quaternion formula uses"));

    // A formula node without its body.
    g = fg::test::minimal_graph();
    g["nodes"][0] = {{"id", "f"}, {"type", "fractal.formula"}};
    g["outputs"]["distance"] = "f.distance";
    EXPECT_TRUE(has_error(fg::test::check_front(g), "/nodes/0", "f", "needs its \"formula\""));
}

}  // namespace
