// The shading nodes add their effects, and the shade pass carries code only for the effects a
// scene uses.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "compiler.h"

namespace {

using nlohmann::json;

json sphere_scene(json nodes, json outputs) {
    nodes.push_back({{"id", "ball"}, {"type", "prim.sphere"}});
    outputs["distance"] = "ball";
    return {{"format", "fractograph-graph"}, {"version", 1}, {"nodes", nodes}, {"outputs", outputs}};
}

struct Compiled {
    std::vector<std::string> effects;
    std::string shade;
};

Compiled compile(const json& graph) {
    fg::Diagnostics diag;
    auto r = fg::compile_graph(graph.dump(), fg::NodeLibrary::builtin(), {}, diag);
    EXPECT_TRUE(r) << diag.format();
    Compiled c;
    if (!r) return c;
    c.effects = r->manifest.effects.names();
    for (const auto& p : r->passes)
        if (p.source.name == "shade") c.shade = p.source.glsl;
    return c;
}

bool has(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

TEST(ShadingEffects, a_scene_without_sss_rim_or_emission_compiles_none_of_them_into_the_shade_pass) {
    auto c = compile(sphere_scene(json::array(), json::object()));
    for (const char* e : {"sss", "rim", "emission", "ao"}) EXPECT_FALSE(has(c.effects, e)) << e;
    ASSERT_FALSE(c.shade.empty());
    for (const char* d : {"#define FG_HAS_SSS", "#define FG_HAS_RIM", "#define FG_HAS_EMISSION", "#define FG_HAS_AO"})
        EXPECT_EQ(c.shade.find(d), std::string::npos) << d;
}

TEST(ShadingEffects, fake_sss_rim_and_emission_nodes_add_their_effects_and_their_shade_terms) {
    json nodes = json::array({
        {{"id", "thin"}, {"type", "light.fake_sss"}, {"inputs", {{"depth", 0.05}}}},
        {{"id", "edge"}, {"type", "light.fake_rim"}},
        {{"id", "glowing"}, {"type", "light.emission"}, {"inputs", {{"intensity", 2.0}}}},
        {{"id", "own_normal"}, {"type", "light.normal"}, {"inputs", {{"taps", 6}}}},
        {{"id", "cavities"}, {"type", "light.fake_ao"}, {"inputs", {{"direction", "own_normal"}}}},
    });
    json outputs = {{"sss", "thin"}, {"rim", "edge"}, {"emission", "glowing"}, {"ao", "cavities"}};
    auto c = compile(sphere_scene(nodes, outputs));
    for (const char* e : {"sss", "rim", "emission", "ao"}) EXPECT_TRUE(has(c.effects, e)) << e;
    for (const char* d : {"#define FG_HAS_SSS", "#define FG_HAS_RIM", "#define FG_HAS_EMISSION", "#define FG_HAS_AO"})
        EXPECT_NE(c.shade.find(d), std::string::npos) << d;
    // light.normal computes its own normal: the pass's finite-difference normal is not needed
    // for it (Lambert diffuse still asks for one, as the diffuse output is unbound).
    EXPECT_NE(c.shade.find("fg_light_normal("), std::string::npos);
}

TEST(ShadingEffects, orbit_trap_readers_and_the_palette_blend_add_trap_and_palette) {
    json nodes = json::array({
        {{"id", "bulb"}, {"type", "fractal.mandelbulb"}},
        {{"id", "near_plane"}, {"type", "trap.plane"}, {"inputs", {{"trap", "bulb.trap"}}}},
        {{"id", "near_centre"}, {"type", "trap.point"}, {"inputs", {{"trap", "bulb.trap"}}}},
        {{"id", "colour"}, {"type", "palette.cosine_blend"}, {"inputs", {{"t", "near_centre"}, {"blend", "near_plane"}}}},
    });
    json g = {{"format", "fractograph-graph"}, {"version", 1}, {"nodes", nodes},
              {"outputs", {{"distance", "bulb.distance"}, {"albedo", "colour"}}}};
    auto c = compile(g);
    EXPECT_TRUE(has(c.effects, "trap"));
    EXPECT_TRUE(has(c.effects, "palette"));
}

TEST(ShadingEffects, the_node_showcase_compiles_with_its_shading_effects_and_a_raised_lipschitz_bound) {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/graphs/examples/node_showcase.json");
    std::stringstream ss;
    ss << in.rdbuf();
    fg::Diagnostics diag;
    auto r = fg::compile_graph(ss.str(), fg::NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(r) << diag.format();
    auto effects = r->manifest.effects.names();
    for (const char* e : {"sss", "rim", "emission", "palette"}) EXPECT_TRUE(has(effects, e)) << e;
    // The twist and the displacement stretch space: the march must step more carefully.
    EXPECT_GT(r->manifest.lipschitz_bound, 1.5);
}

}  // namespace
