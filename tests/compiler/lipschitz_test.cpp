// The static Lipschitz bound: propagated node by node, injected as the march's step scale.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/lipschitz_rule.h"
#include "test_support.h"

using fg::test::compile_text;
using nlohmann::json;

namespace {

double bound_of(const json& g) {
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    EXPECT_TRUE(r) << diag.format();
    return r ? r->manifest.lipschitz_bound : -1.0;
}

json scene_with(json nodes, const std::string& distance) {
    return {{"format", "fractograph-graph"}, {"version", 1}, {"nodes", nodes}, {"outputs", {{"distance", distance}}}};
}

double rule(const std::string& text, double L = 1.0, double absmax = 2.0, double absmin = 0.5) {
    std::string error;
    auto r = fg::LipschitzRule::parse(text, error);
    EXPECT_TRUE(r) << error;
    if (!r) return NAN;
    fg::LipschitzEnv env;
    env.lipschitz = [&](const std::string& p) { return p == "c" ? 0.0 : L; };
    env.absmax = [&](const std::string& p) { return p == "inf" ? INFINITY : absmax; };
    env.absmin = [&](const std::string&) { return absmin; };
    env.bounds_radius = 3.0;
    return r->evaluate(env);
}

}  // namespace

TEST(LipschitzRule, evaluates_arithmetic_with_ports_and_functions) {
    EXPECT_DOUBLE_EQ(rule("L(p) + 2 * 3"), 7.0);
    EXPECT_DOUBLE_EQ(rule("L(p) / absmin(s) + L(s) * absmax(p) / absmin(s)^2"), 2.0 + 2.0 / 0.25);
    EXPECT_DOUBLE_EQ(rule("max(L(a), 3, -1)"), 3.0);
    EXPECT_DOUBLE_EQ(rule("sqrt(1 + (absmax(k) * R)^2)"), std::sqrt(1.0 + 36.0));
    EXPECT_DOUBLE_EQ(rule("-L(p) + abs(-4)"), 3.0);
}

TEST(LipschitzRule, a_vanishing_derivative_times_an_unbounded_value_is_zero) {
    // Product rule with a constant factor: L(c) = 0, |x| unbounded; the term must vanish, not be NaN.
    EXPECT_DOUBLE_EQ(rule("L(x) * 2 + L(c) * absmax(inf)"), 2.0);
}

TEST(LipschitzRule, syntax_errors_say_where) {
    std::string error;
    EXPECT_FALSE(fg::LipschitzRule::parse("L(p) + * 2", error));
    EXPECT_NE(error.find("column"), std::string::npos) << error;
    EXPECT_FALSE(fg::LipschitzRule::parse("frobnicate(p)", error));
    EXPECT_NE(error.find("unknown name 'frobnicate'"), std::string::npos) << error;
}

TEST(LipschitzBound, exact_shapes_and_rigid_motions_keep_the_bound_at_one) {
    json nodes = json::array({
        {{"id", "move"}, {"type", "xform.translate"}, {"inputs", {{"offset", {1.0, 0.0, 0.0}}}}},
        {{"id", "turn"}, {"type", "xform.rotate"}, {"inputs", {{"p", "move.p"}, {"angle_deg", 30.0}}}},
        {{"id", "box"}, {"type", "prim.box"}, {"inputs", {{"p", "turn.p"}}}},
        {{"id", "ball"}, {"type", "prim.sphere"}},
        {{"id", "both"}, {"type", "op.smooth_union"}, {"inputs", {{"a", "box"}, {"b", "ball"}, {"k", 0.2}}}},
    });
    EXPECT_DOUBLE_EQ(bound_of(scene_with(nodes, "both")), 1.0);
}

TEST(LipschitzBound, shrinking_space_without_rescaling_the_distance_slows_the_march) {
    // Evaluating a sphere at p / 0.5 makes it half as large but its distance twice too large.
    json nodes = json::array({
        {{"id", "shrink"}, {"type", "xform.scale"}, {"inputs", {{"s", 0.5}}}},
        {{"id", "ball"}, {"type", "prim.sphere"}, {"inputs", {{"p", "shrink.p"}}}},
    });
    EXPECT_DOUBLE_EQ(bound_of(scene_with(nodes, "ball")), 2.0);
    // Rescaling the distance restores an exact distance.
    nodes.push_back({{"id", "fix"}, {"type", "op.scale_distance"}, {"inputs", {{"d", "ball"}, {"s", 0.5}}}});
    EXPECT_DOUBLE_EQ(bound_of(scene_with(nodes, "fix")), 1.0);
}

TEST(LipschitzBound, a_parameter_driven_scale_uses_the_parameter_range) {
    json g = scene_with(json::array({
                            {{"id", "shrink"}, {"type", "xform.scale"}, {"inputs", {{"s", "$size"}}}},
                            {{"id", "ball"}, {"type", "prim.sphere"}, {"inputs", {{"p", "shrink.p"}}}},
                        }),
                        "ball");
    g["params"] = {{"size", {{"type", "float"}, {"default", 1.0}, {"min", 0.25}, {"max", 4.0}}}};
    // The worst case over the range: s = 0.25.
    EXPECT_DOUBLE_EQ(bound_of(g), 4.0);
}

TEST(LipschitzBound, multiplying_a_distance_by_a_derived_constant_samples_its_range) {
    json g = scene_with(json::array({
                            {{"id", "k"}, {"type", "math.add"}, {"inputs", {{"a", "$gain"}, {"b", 1.0}}}},
                            {{"id", "ball"}, {"type", "prim.sphere"}},
                            {{"id", "big"}, {"type", "math.multiply"}, {"inputs", {{"a", "ball"}, {"b", "k"}}}},
                        }),
                        "big");
    g["params"] = {{"gain", {{"type", "float"}, {"default", 0.0}, {"min", 0.0}, {"max", 1.0}}}};
    // k = gain + 1 <= 2, sampled at the range's corners, widened by 10 %.
    EXPECT_NEAR(bound_of(g), 2.2, 1e-9);
}
