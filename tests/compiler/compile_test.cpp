// The whole compiler on real graphs: real glslang, SPIRV-Tools and SPIRV-Cross.
#include <gtest/gtest.h>

#include <filesystem>

#include "spirv/spirv_optimizer.h"
#include "test_support.h"

using fg::test::compile_text;
using fg::test::has_error;
using fg::test::minimal_graph;
using nlohmann::json;

namespace {

std::vector<std::string> gallery() { return fg::test::graph_files("graphs/gallery"); }

const fg::CompiledPass* find_pass(const fg::CompileResult& r, const std::string& name) {
    for (const auto& p : r.passes)
        if (p.source.name == name) return &p;
    return nullptr;
}

json custom_warp() {
    return {{"id", "warp"},
            {"type", "custom.glsl"},
            {"ports",
             {{"inputs", {{{"name", "p"}, {"type", "vec3"}, {"default", "position"}}}},
              {"outputs", {{{"name", "d"}, {"type", "float"}}}}}},
            {"lipschitz", 2.0},
            {"code", json::array({"vec3 q = p * 2.0;", "d = 0.5 * (length(q) - 1.0);"})}};
}

}  // namespace

TEST(Compile, every_gallery_graph_compiles_into_passes_that_pass_spirv_val) {
    auto files = gallery();
    ASSERT_FALSE(files.empty());
    for (const auto& f : files) {
        fg::Diagnostics diag;
        auto r = compile_text(fg::test::read_source_file(std::filesystem::relative(f, FG_SOURCE_DIR).string()), diag, "graphs/gallery");
        ASSERT_TRUE(r) << f << "\n" << diag.format();
        ASSERT_FALSE(r->passes.empty());
        for (const auto& p : r->passes) {
            fg::Diagnostics val;
            EXPECT_TRUE(fg::validate_spirv(p.source.name, p.spirv, val)) << f << " " << val.format();
        }
    }
}

TEST(Compile, accuracy_knobs_are_specialization_constants_of_the_march_passes) {
    fg::Diagnostics diag;
    auto r = compile_text(fg::test::read_source_file("graphs/gallery/mandelbulb.json"), diag);
    ASSERT_TRUE(r) << diag.format();
    const auto& m = r->manifest;
    for (const char* pass : {"naive", "conemarch"}) {
        const auto* mp = m.find_pass(pass);
        ASSERT_NE(mp, nullptr) << pass;
        for (const char* knob : {"epsilon", "step_scale", "bias.bulb", "iterations.bulb"}) {
            const auto* s = m.find_spec(knob);
            ASSERT_NE(s, nullptr) << knob;
            EXPECT_NE(std::find(mp->spec_constants.begin(), mp->spec_constants.end(), s->id), mp->spec_constants.end())
                << knob << " is not a specialization constant of " << pass;
        }
    }
    EXPECT_EQ(m.find_spec("iterations.bulb")->value, 8);
    ASSERT_EQ(m.fractals.size(), 1u);
    EXPECT_EQ(m.fractals[0].bias_spec, m.find_spec("bias.bulb")->id);
    for (const auto& s : m.spec_constants) EXPECT_NE(s.id, 0u);
}

TEST(Compile, parameters_are_uniforms_whose_offsets_match_reflection) {
    auto g = minimal_graph();
    g["params"]["tint"] = {{"type", "vec3"}, {"default", {1.0, 0.5, 0.25}}};
    g["params"]["gain"] = {{"type", "float"}, {"default", 2.0}};
    g["nodes"][1]["inputs"]["a"] = "$tint";
    g["nodes"][1]["inputs"]["t"] = "$gain";
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_FALSE(diag.has_errors()) << diag.format();  // the compiler checks reflection against std140
    const auto& m = r->manifest;
    ASSERT_EQ(m.params.size(), 3u);
    // Declaration order follows the graph document (object keys sorted): gain, radius, tint.
    EXPECT_EQ(m.find_param("gain")->offset, 0u);
    EXPECT_EQ(m.find_param("radius")->offset, 4u);
    EXPECT_EQ(m.find_param("tint")->offset, 16u);
    EXPECT_EQ(m.params_size, 32u);
}

TEST(Compile, constant_inputs_are_folded_by_the_cpu_twin) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "two"}, {"type", "math.add"}, {"inputs", {{"a", 0.5}, {"b", 0.25}}}});
    g["nodes"].push_back({{"id", "grow"}, {"type", "math.multiply"}, {"inputs", {{"a", "two"}, {"b", 2.0}}}});
    g["nodes"][0]["inputs"]["radius"] = "grow";
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_EQ(r->folding.folded, 3);  // add, multiply, and the palette with its literal t
    EXPECT_EQ(r->ir.find("two"), -1);
    EXPECT_EQ(r->ir.find("grow"), -1);
    const auto& ball = r->ir.nodes[static_cast<std::size_t>(r->ir.find("ball"))];
    EXPECT_EQ(ball.inputs[1].kind, fg::IrInput::Kind::Constant);
    EXPECT_DOUBLE_EQ(ball.inputs[1].constant.v[0], 1.5);
    EXPECT_NE(find_pass(*r, "naive")->source.glsl.find("fg_prim_sphere(p, 1.5, "), std::string::npos);
}

TEST(Compile, a_node_that_folds_to_infinity_is_an_error) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "bad"}, {"type", "math.divide"}, {"inputs", {{"a", 1.0}, {"b", 0.0}}}});
    g["nodes"][0]["inputs"]["radius"] = "bad";
    fg::Diagnostics diag;
    EXPECT_FALSE(compile_text(g.dump(), diag));
    EXPECT_TRUE(has_error(diag, "/nodes/2", "bad", "computes inf"));
}

TEST(Compile, nodes_no_output_reaches_are_removed_with_a_note) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "unused"}, {"type", "prim.box"}});
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_EQ(r->ir.find("unused"), -1);
    bool noted = false;
    for (const auto& d : diag.items()) noted |= d.severity == fg::Severity::Note && d.node_id == "unused";
    EXPECT_TRUE(noted);
    for (const auto& p : r->passes) EXPECT_EQ(p.source.glsl.find("fg_prim_box"), std::string::npos) << p.source.name;
}

TEST(Compile, the_distance_function_leaves_out_what_only_shading_needs) {
    fg::Diagnostics diag;
    auto r = compile_text(fg::test::read_source_file("graphs/gallery/mandelbulb.json"), diag);
    ASSERT_TRUE(r) << diag.format();
    const auto& naive = find_pass(*r, "naive")->source.glsl;
    EXPECT_EQ(naive.find("fg_palette_cosine"), std::string::npos);
    EXPECT_EQ(naive.find("fg_scene_surface"), std::string::npos);
    EXPECT_NE(find_pass(*r, "shade")->source.glsl.find("fg_palette_cosine("), std::string::npos);
}

TEST(Compile, a_custom_node_compiles_and_its_declared_bound_scales_the_step) {
    auto g = minimal_graph();
    g["nodes"].push_back(custom_warp());
    g["outputs"]["distance"] = "warp.d";
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_DOUBLE_EQ(r->manifest.lipschitz_bound, 2.0);
    EXPECT_DOUBLE_EQ(r->manifest.find_spec("step_scale")->value, 0.5);
}

TEST(Compile, a_glsl_error_in_custom_code_is_reported_against_the_node_and_its_line) {
    auto g = minimal_graph();
    auto warp = custom_warp();
    warp["code"] = json::array({"vec3 q = p * 2.0;", "d = 0.5 * (lenght(q) - 1.0);"});
    g["nodes"].push_back(warp);
    g["outputs"]["distance"] = "warp.d";
    fg::Diagnostics diag;
    EXPECT_FALSE(compile_text(g.dump(), diag));
    EXPECT_TRUE(has_error(diag, "/nodes/2/code", "warp", "in the node's code, line 2: 'lenght' : no matching overloaded function"))
        << diag.format();
    // The generated line is shown as context.
    bool context = false;
    for (const auto& d : diag.items()) context |= d.context.find("lenght(q)") != std::string::npos;
    EXPECT_TRUE(context);
}

TEST(Compile, custom_code_cannot_break_out_of_its_function) {
    auto g = minimal_graph();
    auto warp = custom_warp();
    warp["code"] = "d = 1.0; } void main() { ";
    g["nodes"].push_back(warp);
    g["outputs"]["distance"] = "warp.d";
    fg::Diagnostics diag;
    EXPECT_FALSE(compile_text(g.dump(), diag));
    EXPECT_TRUE(has_error(diag, "/nodes/2/code", "warp", "unbalanced braces"));
}

TEST(Compile, an_unknown_lipschitz_rule_falls_back_with_a_warning) {
    auto g = minimal_graph();
    g["nodes"].push_back({{"id", "shape"}, {"type", "math.pow"}, {"inputs", {{"x", "ball"}, {"e", 1.0}}}});
    g["outputs"]["distance"] = "shape";
    fg::Diagnostics diag;
    auto r = compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_FALSE(r->manifest.lipschitz_exact);
    EXPECT_DOUBLE_EQ(r->manifest.lipschitz_bound, 1.0);
    bool warned = false;
    for (const auto& d : diag.items())
        warned |= d.severity == fg::Severity::Warning && d.message.find("unbounded at node \"shape\"") != std::string::npos;
    EXPECT_TRUE(warned) << diag.format();
}

TEST(Compile, a_lobe_bound_for_the_environment_in_a_scene_without_one_is_warned_of) {
    auto g = minimal_graph();
    g["outputs"]["specular_color"] = json::array({1.0, 0.8, 0.4});
    auto warned = [&](const nlohmann::json& graph) {
        fg::Diagnostics diag;
        EXPECT_TRUE(compile_text(graph.dump(), diag)) << diag.format();
        for (const auto& d : diag.items())
            if (d.severity == fg::Severity::Warning && d.pointer == "/outputs/specular_color" &&
                d.message.find("add scene.environment") != std::string::npos)
                return true;
        return false;
    };
    EXPECT_TRUE(warned(g));
    g["scene"]["environment"] = {{"color", {1.0, 1.0, 1.0}}};
    EXPECT_FALSE(warned(g));
}
