// Every node's body computes the same thing on the GPU (float, lavapipe in CI) and in the CPU twin
// (the same text compiled as C++ in double precision), at a few hundred random points inside the
// ports' declared ranges, in one dispatch per node and generic instance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fmt/format.h>

#include "compiler.h"
#include "cpu/cpu_evaluator.h"
#include "cpu/cpu_node_registry.h"
#include "every_node.h"
#include "gpu_node_evaluator.h"

namespace {

constexpr std::size_t kPoints = 256;

// Float against double: relative where values are large, absolute near zero.
bool agrees(double gpu, double cpu, double tolerance = 2e-4) {
    return std::abs(gpu - cpu) <= tolerance * (1.0 + std::abs(cpu));
}

struct Comparison {
    std::size_t mismatches = 0;
    std::size_t non_finite = 0;
    std::string first;
};

// Compares the GPU's answers for `def` with its CPU twin's.
// With `in_double` the body runs lowered to double on the GPU (precision "double"), with the
// double math of nodes/double_math.glsl, and the tolerances shrink accordingly.
Comparison compare(const fg::NodeDefinition& def, std::optional<fg::ValueType> generic, std::uint32_t seed,
                   bool in_double = false) {
    std::mt19937 rng(seed);
    std::vector<fg::CpuValue> inputs;
    for (std::size_t i = 0; i < kPoints; ++i) {
        auto v = fg::test::random_inputs(def, generic, rng);
        if (v.empty()) v.resize(1);
        inputs.insert(inputs.end(), v.begin(), v.end());
    }
    const std::size_t nin = std::max<std::size_t>(def.inputs.size(), 1), nout = def.outputs.size();
    fg::Diagnostics diag;
    auto gpu = fg::test::GpuNodeEvaluator::shared().evaluate(def, generic, inputs, kPoints, diag, in_double);
    Comparison c;
    if (!gpu) {
        ADD_FAILURE() << "the evaluation shader did not compile:\n" << diag.format();
        c.mismatches = kPoints;
        return c;
    }
    auto function = fg::find_cpu_node(def.type, generic);
    if (!function) {
        ADD_FAILURE() << "no CPU twin for " << def.type;
        c.mismatches = kPoints;
        return c;
    }
    // Shade-context bodies ask for the scene distance: the same unit sphere the shader has.
    fg::Diagnostics scene_diag;
    auto scene_ir = fg::load_and_lower(fg::test::unit_sphere_scene(), fg::NodeLibrary::builtin(), scene_diag);
    auto scene = fg::CpuEvaluator::create(*scene_ir, scene_diag);
    fg::CpuShadingScope shading(*scene);

    // An iterated map amplifies float rounding each iteration (about by the power per step for a
    // Mandelbulb), and orbit traps keep the minimum over the orbit: compare those within 1 %.
    // In double both sides round alike; iterated maps still part near the surface, much later.
    const double tolerance = in_double ? (fg::test::is_iterated(def) ? 1e-6 : 1e-10)
                                       : (fg::test::is_iterated(def) ? 1e-2 : 2e-4);
    std::vector<fg::CpuValue> out(nout);
    for (std::size_t i = 0; i < kPoints; ++i) {
        function(&inputs[i * nin], out.data());
        bool ok = true;
        std::string detail;
        for (std::size_t k = 0; k < nout; ++k) {
            const int n = fg::component_count(fg::test::concrete_type(def.outputs[k].type, generic));
            for (int comp = 0; comp < n; ++comp) {
                double want = out[k].v[comp], got = (*gpu)[i * nout + k].v[comp];
                if (!std::isfinite(want)) ++c.non_finite;
                if (!agrees(got, want, tolerance)) {
                    ok = false;
                    detail += fmt::format(" {}[{}]: GPU {:.9g}, CPU {:.9g};", def.outputs[k].name, comp, got, want);
                }
            }
        }
        if (!ok) {
            if (c.mismatches == 0) {
                std::string args;
                for (std::size_t k = 0; k < def.inputs.size(); ++k) {
                    const auto& v = inputs[i * nin + k].v;
                    args += fmt::format(" {}=({:.7g}, {:.7g}, {:.7g}, {:.7g})", def.inputs[k].name, v.x, v.y, v.z, v.w);
                }
                c.first = fmt::format("point {}:{}\n  inputs:{}", i, detail, args);
            }
            ++c.mismatches;
        }
    }
    return c;
}

class NodeTwin : public ::testing::TestWithParam<std::string> {};

TEST_P(NodeTwin, gpu_and_cpu_twin_agree_at_random_points) {
    const auto& def = fg::test::library_node(GetParam());
    const auto errors_before = fg::test::GpuNodeEvaluator::shared().context().validation_errors();
    for (auto generic : fg::test::instances_of(def)) {
        SCOPED_TRACE(fg::test::instance_name(def, generic));
        auto c = compare(def, generic, 20261123u);
        EXPECT_EQ(c.non_finite, 0u) << "the CPU twin produced NaN or Inf inside the declared ranges";
        // Chaotic iterations: float and double orbits may part near the surface at a few points.
        const std::size_t allowed = fg::test::is_iterated(def) ? kPoints / 20 : 0;
        if (allowed) std::printf("%s: %zu of %zu points beyond 1 %%\n", def.type.c_str(), c.mismatches, kPoints);
        EXPECT_LE(c.mismatches, allowed) << c.mismatches << " of " << kPoints << " points disagree; first " << c.first;
    }
    EXPECT_EQ(fg::test::GpuNodeEvaluator::shared().context().validation_errors(), errors_before);
}

// Precision "double": every body lowered as fgc lowers it agrees with the CPU twin (also double)
// far more closely than float can, which checks the lowering and the double math together.
TEST_P(NodeTwin, double_variant_agrees_with_the_cpu_twin) {
    const auto& def = fg::test::library_node(GetParam());
    auto& gpu = fg::test::GpuNodeEvaluator::shared();
    if (!gpu.context().shader_float64_enabled()) GTEST_SKIP() << "no shaderFloat64 on " << gpu.context().device_name();
    const auto errors_before = gpu.context().validation_errors();
    for (auto generic : fg::test::instances_of(def)) {
        SCOPED_TRACE(fg::test::instance_name(def, generic));
        auto c = compare(def, generic, 20261124u, true);
        EXPECT_EQ(c.non_finite, 0u);
        const std::size_t allowed = fg::test::is_iterated(def) ? kPoints / 50 : 0;
        if (c.mismatches) std::printf("%s (double): %zu of %zu points beyond tolerance\n", def.type.c_str(), c.mismatches, kPoints);
        EXPECT_LE(c.mismatches, allowed) << c.mismatches << " of " << kPoints << " points disagree; first " << c.first;
    }
    EXPECT_EQ(gpu.context().validation_errors(), errors_before);
}

FG_FOR_EVERY_NODE(NodeTwin);

// The comparison has teeth: a box's GPU answers do not pass for a sphere's CPU twin.
TEST(NodeTwinCheck, notices_a_body_that_computes_something_else) {
    const auto& box = fg::test::library_node("prim.box");
    const auto& sphere = fg::test::library_node("prim.sphere");
    ASSERT_EQ(box.inputs.size(), 3u);
    ASSERT_EQ(sphere.inputs.size(), 2u);
    // Evaluate the box on the GPU; compare with the sphere's CPU body on the box's point and
    // size.x as the radius: they differ almost everywhere.
    std::mt19937 rng(7u);
    std::vector<fg::CpuValue> inputs;
    for (std::size_t i = 0; i < kPoints; ++i) {
        auto v = fg::test::random_inputs(box, std::nullopt, rng);
        inputs.insert(inputs.end(), v.begin(), v.end());
    }
    fg::Diagnostics diag;
    auto gpu = fg::test::GpuNodeEvaluator::shared().evaluate(box, std::nullopt, inputs, kPoints, diag);
    ASSERT_TRUE(gpu) << diag.format();
    auto sphere_fn = fg::find_cpu_node("prim.sphere", std::nullopt);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < kPoints; ++i) {
        fg::CpuValue in[2] = {inputs[i * 3], fg::CpuValue::of(inputs[i * 3 + 1].v.x)}, out[1];
        sphere_fn(in, out);
        differ += agrees((*gpu)[i].v.x, out[0].v.x) ? 0 : 1;
    }
    EXPECT_GT(differ, kPoints / 2);
}

}  // namespace
