// The fractal nodes keep their promises on the CPU twin: every one is documented like the others
// (running derivative, bias and iterations knobs, orbit trap, example), stays finite at the hard
// points (origin, axes, far away, tiny) for every parameter at either end of its range, and the
// plain Menger sponge's estimate is its exact distance where that is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cpu/cpu_node_registry.h"
#include "graph/node_library.h"

using namespace fg;

namespace {

std::vector<const NodeDefinition*> fractal_nodes() {
    std::vector<const NodeDefinition*> out;
    for (const auto* d : NodeLibrary::builtin().all())
        if (d->namespace_name() == "fractal" && !d->generated_body()) out.push_back(d);
    return out;
}

std::vector<CpuValue> default_inputs(const NodeDefinition& def, const glm::dvec3& p) {
    std::vector<CpuValue> in;
    for (const auto& port : def.inputs)
        in.push_back(port.implicit == ImplicitSource::Position ? CpuValue::of(p) : CpuValue::of(*port.default_value));
    return in;
}

std::size_t input_index(const NodeDefinition& def, const std::string& name) {
    for (std::size_t i = 0; i < def.inputs.size(); ++i)
        if (def.inputs[i].name == name) return i;
    ADD_FAILURE() << def.type << " has no input " << name;
    return 0;
}

struct Result {
    double distance;
    glm::dvec4 trap;
};

Result evaluate(const NodeDefinition& def, const std::vector<CpuValue>& in) {
    CpuNodeFunction f = find_cpu_node(def.type, std::nullopt);
    std::vector<CpuValue> out(def.outputs.size());
    f(in.data(), out.data());
    return {out[0].f(), out[1].v4()};
}

bool finite(const Result& r) {
    return std::isfinite(r.distance) && std::isfinite(r.trap.x) && std::isfinite(r.trap.y) && std::isfinite(r.trap.z) &&
           std::isfinite(r.trap.w);
}

const std::vector<glm::dvec3> kHardPoints{
    {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}, {1, 1, 1}, {-1, 1, -1}, {1e-6, 0, 0}, {0, 1e-30, 0},
    {1e6, 0, 0}, {-1e6, 1e6, 3}, {0.5, 0.5, 0.5}, {2, 0, 0}, {0, 0, -4}, {1.0 / 3.0, 1.0 / 3.0, 0.0}};

}  // namespace

TEST(FractalNodes, the_library_has_every_family_the_gallery_needs) {
    for (const char* t : {"fractal.mandelbulb", "fractal.mandelbox", "fractal.menger", "fractal.kifs", "fractal.julia",
                          "fractal.apollonian", "fractal.kleinian", "fractal.fold_iterate"})
        EXPECT_NE(NodeLibrary::builtin().find(t), nullptr) << t;
}

TEST(FractalNodes, each_has_a_running_derivative_knobs_a_trap_and_an_example) {
    for (const auto* def : fractal_nodes()) {
        SCOPED_TRACE(def->type);
        EXPECT_FALSE(def->running_derivative.empty());
        EXPECT_TRUE(def->lipschitz.count("distance"));
        EXPECT_TRUE(def->example.contains("inputs"));
        bool bias = false, iterations = false;
        for (const auto& p : def->inputs) {
            bias = bias || p.knob == "bias";
            iterations = iterations || p.knob == "iterations";
        }
        EXPECT_TRUE(bias && iterations);
        // Fractals that escape by a bailout also say after how many iterations (iteration fog).
        ASSERT_GE(def->outputs.size(), 2u);
        ASSERT_LE(def->outputs.size(), 3u);
        EXPECT_EQ(def->outputs[0].name, "distance");
        EXPECT_EQ(def->outputs[1].name, "trap");
        EXPECT_EQ(def->outputs[1].effect, Effect::OrbitTrap);
        if (def->outputs.size() == 3) EXPECT_EQ(def->outputs[2].name, "escape");
        EXPECT_NE(def->glsl.find("fg_conservative_dr"), std::string::npos) << "the bias must guard the derivative";
    }
}

TEST(FractalNodes, stay_finite_at_hard_points_for_every_parameter_at_either_end_of_its_range) {
    for (const auto* def : fractal_nodes()) {
        for (const auto& p : kHardPoints) {
            auto base = default_inputs(*def, p);
            std::vector<std::vector<CpuValue>> settings{base};
            for (std::size_t i = 0; i < def->inputs.size(); ++i) {
                const auto& port = def->inputs[i];
                for (auto bound : {port.min, port.max}) {
                    if (!bound) continue;
                    auto in = base;
                    for (int c = 0; c < 4; ++c) in[i].v[c] = *bound;
                    settings.push_back(in);
                }
            }
            for (const auto& in : settings) {
                Result r = evaluate(*def, in);
                EXPECT_TRUE(finite(r)) << def->type << " at (" << p.x << ", " << p.y << ", " << p.z
                                       << "): distance " << r.distance;
            }
        }
    }
}

TEST(FractalNodes, far_away_points_are_far_and_the_estimate_does_not_exceed_the_distance_to_the_origin_by_much) {
    // Bounded fractals seen from 1e3: the estimate is positive and at most the distance to the
    // origin plus the fractal's size (the apollonian and kleinian ones fill space and are left out).
    for (const auto* def : fractal_nodes()) {
        if (def->type == "fractal.apollonian" || def->type == "fractal.kleinian") continue;
        glm::dvec3 p(600.0, -500.0, 640.0);
        Result r = evaluate(*def, default_inputs(*def, p));
        EXPECT_GT(r.distance, 0.0) << def->type;
        EXPECT_LE(r.distance, glm::length(p) + 8.0) << def->type;
    }
}

TEST(FractalNodes, the_plain_menger_sponge_estimate_is_its_exact_distance) {
    const auto* def = NodeLibrary::builtin().find("fractal.menger");
    ASSERT_NE(def, nullptr);
    // Outside a corner the nearest point is the corner (1, 1, 1), solid at every level.
    EXPECT_NEAR(evaluate(*def, default_inputs(*def, {2, 2, 2})).distance, std::sqrt(3.0), 1e-9);
    // Beyond a face, straight out from a solid edge cube of the first level.
    EXPECT_NEAR(evaluate(*def, default_inputs(*def, {3, 1, 1})).distance, 2.0, 1e-9);
    // The centre is hollow: the nearest solid is the edge of the central cross, (1/3, 1/3, z).
    EXPECT_NEAR(evaluate(*def, default_inputs(*def, {0, 0, 0})).distance, std::sqrt(2.0) / 3.0, 1e-9);
}

TEST(FractalNodes, near_the_escape_ball_the_estimate_is_not_capped_to_zero) {
    // Capping by |p| - R right at the ball would make a false surface there.
    for (const char* type : {"fractal.julia", "fractal.mandelbulb"}) {
        const auto* def = NodeLibrary::builtin().find(type);
        EXPECT_GT(evaluate(*def, default_inputs(*def, {2.05, 0.0, 0.0})).distance, 0.3) << type;
    }
}

TEST(FractalNodes, the_julia_estimate_never_exceeds_the_distance_to_its_bounding_ball_far_away) {
    const auto* def = NodeLibrary::builtin().find("fractal.julia");
    ASSERT_NE(def, nullptr);
    for (double r : {4.5, 10.0, 100.0, 1e5}) {
        glm::dvec3 p(r, 0.0, 0.0);
        EXPECT_LE(evaluate(*def, default_inputs(*def, p)).distance, r - 2.0 + 1e-12) << r;
    }
}


TEST(FractalNodes, fold_iterate_with_the_mandelbox_stages_is_the_mandelbox) {
    const auto* box = NodeLibrary::builtin().find("fractal.mandelbox");
    const auto* generic = NodeLibrary::builtin().find("fractal.fold_iterate");
    ASSERT_TRUE(box && generic);
    std::srand(3);
    auto rnd = [] { return 4.0 * std::rand() / RAND_MAX - 2.0; };
    for (int i = 0; i < 500; ++i) {
        glm::dvec3 p(rnd(), rnd(), rnd());
        auto a = default_inputs(*box, p);
        a[input_index(*box, "scale")] = CpuValue::of(-1.5);
        auto b = default_inputs(*generic, p);
        b[input_index(*generic, "box_limit")] = CpuValue::of(1.0);
        b[input_index(*generic, "min_radius")] = CpuValue::of(0.5);
        b[input_index(*generic, "fixed_radius")] = CpuValue::of(1.0);
        b[input_index(*generic, "scale")] = CpuValue::of(-1.5);
        b[input_index(*generic, "add_point")] = CpuValue::of(1.0);
        b[input_index(*generic, "iterations")] = CpuValue::of(12);
        Result ra = evaluate(*box, a), rb = evaluate(*generic, b);
        ASSERT_NEAR(ra.distance, rb.distance, 1e-9 * (1.0 + std::abs(ra.distance))) << p.x << " " << p.y << " " << p.z;
    }
}
