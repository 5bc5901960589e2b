// The compiler finds which effects a scene uses, emits code only for those and lists them in the
// manifest, so the runtime allocates and runs nothing else.
#include <gtest/gtest.h>

#include "test_support.h"

using fg::Effect;
using fg::test::compile_text;
using fg::test::minimal_graph;
using nlohmann::json;

namespace {

fg::CompileResult compile(const json& g) {
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    EXPECT_TRUE(r) << diag.format();
    return r ? std::move(*r) : fg::CompileResult{};
}

bool has_pass(const fg::CompileResult& r, const std::string& name) { return r.manifest.find_pass(name) != nullptr; }

const std::string& glsl(const fg::CompileResult& r, const std::string& pass) {
    for (const auto& p : r.passes)
        if (p.source.name == pass) return p.source.glsl;
    static const std::string none;
    return none;
}

}  // namespace

TEST(EffectSet, a_scene_without_fog_glow_or_vignette_gets_no_post_effect_code) {
    auto r = compile(minimal_graph());
    EXPECT_FALSE(r.manifest.effects.has(Effect::Fog));
    EXPECT_FALSE(r.manifest.effects.has(Effect::Glow));
    for (const char* effect : {"FOG", "GLOW", "VIGNETTE"})
        EXPECT_EQ(glsl(r, "shade").find(std::string("#define FG_HAS_") + effect), std::string::npos) << effect;
}

// Post effects are functions of one pixel: the shade pass applies them, no pass of their own.
TEST(EffectSet, fog_in_the_scene_adds_the_effect_to_the_shade_pass_and_no_post_pass) {
    auto g = minimal_graph();
    g["scene"]["fog"] = {{"density", 0.2}};
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Fog));
    EXPECT_FALSE(r.manifest.effects.has(Effect::Glow));
    EXPECT_NE(glsl(r, "shade").find("#define FG_HAS_FOG"), std::string::npos);
    EXPECT_FALSE(has_pass(r, "post"));
    // No glow image is bound by any pass.
    for (const auto& p : r.manifest.passes)
        for (const auto& b : p.bindings) EXPECT_NE(b.name, "fg_glow") << p.name;
}

TEST(EffectSet, glow_adds_a_glow_image_to_the_march_and_shade_passes) {
    auto g = minimal_graph();
    g["scene"]["glow"] = {{"intensity", 0.5}};
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Glow));
    for (const char* pass : {"naive", "conemarch", "shade"}) {
        bool bound = false;
        for (const auto& b : r.manifest.find_pass(pass)->bindings) bound |= b.name == "fg_glow";
        EXPECT_TRUE(bound) << pass;
    }
}

TEST(EffectSet, the_trap_effect_comes_only_from_using_a_trap_output) {
    json g = minimal_graph();
    g["nodes"].push_back({{"id", "bulb"}, {"type", "fractal.mandelbulb"}});
    g["outputs"]["distance"] = "bulb.distance";
    EXPECT_FALSE(compile(g).manifest.effects.has(Effect::OrbitTrap));
    g["nodes"].push_back({{"id", "split"}, {"type", "math.split4"}, {"inputs", {{"v", "bulb.trap"}}}});
    g["nodes"][1]["inputs"]["t"] = "split.w";
    EXPECT_TRUE(compile(g).manifest.effects.has(Effect::OrbitTrap));
}

TEST(EffectSet, fake_lighting_nodes_add_their_effects_and_no_normals) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "light"}, {"type", "light.fake_diffuse"}});
    g["nodes"].push_back({{"id", "occ"}, {"type", "light.fake_ao"}});
    g["outputs"]["diffuse"] = "light";
    g["outputs"]["ao"] = "occ";
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Diffuse));
    EXPECT_TRUE(r.manifest.effects.has(Effect::AmbientOcclusion));
    EXPECT_FALSE(r.manifest.effects.has(Effect::Normals));
    EXPECT_EQ(glsl(r, "shade").find("#define FG_HAS_NORMALS"), std::string::npos);
}

TEST(EffectSet, an_unbound_diffuse_falls_back_to_lambert_and_needs_normals) {
    auto r = compile(minimal_graph());
    EXPECT_TRUE(r.manifest.effects.has(Effect::Normals));
    EXPECT_FALSE(r.manifest.effects.has(Effect::Diffuse));
}

TEST(EffectSet, code_of_unused_effects_is_not_in_the_spirv) {
    auto plain = compile(minimal_graph());
    auto g = minimal_graph();
    g["scene"]["fog"] = {{"density", 0.2}};
    g["scene"]["glow"] = {{"intensity", 0.5}};
    auto fancy = compile(g);
    // The naive pass writes a glow image only when glow is used: its SPIR-V grows with it.
    std::size_t plain_words = 0, fancy_words = 0;
    for (const auto& p : plain.passes)
        if (p.source.name == "naive") plain_words = p.spirv.size();
    for (const auto& p : fancy.passes)
        if (p.source.name == "naive") fancy_words = p.spirv.size();
    EXPECT_LT(plain_words, fancy_words);
}

TEST(EffectSet, scene_settings_turn_on_vignette_and_background_gradient) {
    auto g = minimal_graph();
    g["scene"]["vignette"] = {{"strength", 0.3}};
    g["scene"]["background"] = {{"top", {0.2, 0.3, 0.5}}, {"bottom", {0.0, 0.0, 0.0}}};
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Vignette));
    EXPECT_TRUE(r.manifest.effects.has(Effect::BackgroundGradient));
    EXPECT_NE(glsl(r, "shade").find("#define FG_HAS_VIGNETTE"), std::string::npos);
    EXPECT_FALSE(has_pass(r, "post"));
}

TEST(EffectSet, glass_is_compiled_only_where_the_graph_binds_a_transmission) {
    auto plain = compile(minimal_graph());
    EXPECT_FALSE(plain.manifest.effects.has(Effect::Refraction));
    EXPECT_EQ(glsl(plain, "shade").find("#define FG_HAS_REFRACTION"), std::string::npos);
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "glass"}, {"type", "light.refraction"}});
    g["outputs"]["transmission"] = "glass.transmission";
    g["outputs"]["ior"] = "glass.ior";
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Refraction));
    EXPECT_TRUE(r.manifest.effects.has(Effect::Normals)) << "the ray bends about the shade pass's normal";
    EXPECT_NE(glsl(r, "shade").find("#define FG_HAS_REFRACTION"), std::string::npos);
    EXPECT_NE(glsl(r, "aov").find("#define FG_HAS_REFRACTION"), std::string::npos);
}

TEST(EffectSet, a_medium_is_compiled_only_where_the_graph_binds_a_volume_density) {
    auto plain = compile(minimal_graph());
    EXPECT_FALSE(plain.manifest.effects.has(Effect::Volume));
    EXPECT_EQ(glsl(plain, "shade").find("vec4 fg_scene_volume("), std::string::npos);
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "fog"}, {"type", "light.iteration_fog"}, {"inputs", {{"escape", "ball.distance"}}}});
    g["outputs"]["volume_density"] = "fog.density";
    g["outputs"]["volume_color"] = "fog.color";
    auto r = compile(g);
    EXPECT_TRUE(r.manifest.effects.has(Effect::Volume));
    for (const char* pass : {"shade", "aov"}) {
        EXPECT_NE(glsl(r, pass).find("#define FG_HAS_VOLUME"), std::string::npos) << pass;
        EXPECT_NE(glsl(r, pass).find("vec4 fg_scene_volume("), std::string::npos) << pass;
    }
    // The medium is not a surface output: the hit's shading does not evaluate it.
    const std::string shade = glsl(r, "shade");
    const std::string surface = shade.substr(shade.find("FgSurface fg_scene_surface("), shade.find("return s;", shade.find("FgSurface fg_scene_surface(")) - shade.find("FgSurface fg_scene_surface("));
    EXPECT_EQ(surface.find("fg_light_iteration_fog("), std::string::npos) << surface;
}
