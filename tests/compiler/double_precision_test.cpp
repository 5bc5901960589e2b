// Precision "double" (scene.precision, fgc compile --precision): node GLSL lowered to double, the
// scene evaluated around the camera, the choice recorded in the pack.
#include <gtest/gtest.h>

#include <algorithm>

#include "codegen/double_lowering.h"
#include "pack/pack_reader.h"
#include "test_support.h"

namespace {

using nlohmann::json;

TEST(DoubleLowering, rewrites_types_literals_and_transcendentals_and_leaves_comments_and_names_alone) {
    const std::string body = "// float pow of vec3\n"
                             "float fg_x(vec3 p, int n, OUT(vec4) trap) {\n"
                             "    float r = 0.5 * pow(length(p), 8.0) + 1e-20 + .25 + 2.5e3;\n"
                             "    mat3 m = mat3(1.0); float n0_1 = FG_KNOB_3 + float(n) + atan(p.x, p.z);\n"
                             "    return fg_scene_distance(p) + exp(r) * 3; /* sin(x) stays */ }\n";
    const std::string lowered = fg::lower_to_double(body);
    EXPECT_EQ(lowered,
              "// float pow of vec3\n"
              "double fg_x(dvec3 p, int n, OUT(dvec4) trap) {\n"
              "    double r = 0.5lf * fg_d_pow(length(p), 8.0lf) + 1e-20lf + .25lf + 2.5e3lf;\n"
              "    dmat3 m = dmat3(1.0lf); double n0_1 = FG_KNOB_3 + double(n) + fg_d_atan(p.x, p.z);\n"
              "    return fg_scene_distance_d(p) + fg_d_exp(r) * 3; /* sin(x) stays */ }\n");
    EXPECT_EQ(std::count(lowered.begin(), lowered.end(), '\n'), std::count(body.begin(), body.end(), '\n'));
    // Already double literals keep their suffix.
    EXPECT_EQ(fg::lower_to_double("1.0lf + 2.0f"), "1.0lf + 2.0lf");
}

TEST(DoubleLowering, names_the_functions_that_have_no_double_form) {
    auto f = fg::functions_without_double("float y = tanh(x) + sinh (x) + my_tanh(x) + tanh(y); // dFdx(z)");
    EXPECT_EQ(f, (std::vector<std::string>{"tanh", "sinh"}));
    EXPECT_TRUE(fg::functions_without_double(fg::NodeLibrary::builtin().prelude()).empty());
}

// Every gallery graph and hard case lowers and passes glslang and spirv-val in double: no library
// node needs a function without a double form.
TEST(DoublePrecision, the_gallery_compiles_in_double_and_the_pack_says_so) {
    for (const char* name : {"graphs/gallery/mandelbulb.json", "graphs/gallery/mandelbox.json",
                             "graphs/gallery/menger_twisted.json", "graphs/examples/node_showcase.json",
                             "graphs/gallery/halls_shafts.json", "graphs/gallery/hdri_mandelbulb.json",
                             "graphs/gallery/glass_ball.json"}) {
        SCOPED_TRACE(name);
        fg::Diagnostics diag;
        fg::CompileOptions options;
        options.folder = std::string(FG_SOURCE_DIR) + "/graphs/gallery";   // the sunset sky's
        options.double_precision = true;
        options.include_glsl = true;
        auto result = fg::compile_graph(fg::test::read_source_file(name), fg::NodeLibrary::builtin(), options, diag);
        ASSERT_TRUE(result) << diag.format();
        EXPECT_EQ(result->manifest.precision, "double");
        auto pack = fg::read_pack(fg::pack_bytes(*result), diag);
        ASSERT_TRUE(pack) << diag.format();
        EXPECT_EQ(pack->manifest.precision, "double");
        for (const auto& p : result->passes) {
            // Passes that never evaluate the distance: they only move pixels.
            if (p.source.name == "fovea" || p.source.name == "resolve" || p.source.name == "taa") continue;
            EXPECT_NE(p.source.glsl.find("#define FG_DOUBLE_SCENE 1"), std::string::npos) << p.source.name;
            EXPECT_NE(p.source.glsl.find("double fg_scene_distance_d(dvec3 p)"), std::string::npos) << p.source.name;
        }
    }
}

TEST(DoublePrecision, the_graph_chooses_it_and_the_compile_option_overrides_it) {
    json g = fg::test::minimal_graph();
    g["scene"]["precision"] = "double";
    fg::Diagnostics diag;
    auto dbl = fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(dbl) << diag.format();
    EXPECT_EQ(dbl->manifest.precision, "double");
    EXPECT_TRUE(dbl->manifest.scene.double_precision);
    fg::CompileOptions as_float;
    as_float.double_precision = false;
    auto flt = fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), as_float, diag);
    ASSERT_TRUE(flt) << diag.format();
    EXPECT_EQ(flt->manifest.precision, "float");

    g["scene"]["precision"] = "quad";
    fg::Diagnostics bad;
    EXPECT_FALSE(fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), {}, bad));
    EXPECT_NE(bad.format().find("/scene/precision"), std::string::npos) << bad.format();
}

TEST(DoublePrecision, a_node_that_cannot_be_lowered_is_named_in_the_error) {
    json g = fg::test::minimal_graph();
    g["nodes"].push_back(json::parse(R"({"id": "soft", "type": "custom.glsl",
        "ports": {"inputs": [{"name": "p", "type": "vec3", "default": "position"}],
                  "outputs": [{"name": "d", "type": "float"}]},
        "lipschitz": 1.0, "code": ["d = tanh(length(p)) - 0.5;"]})"));
    g["outputs"]["distance"] = "soft.d";
    fg::Diagnostics float_diag;
    EXPECT_TRUE(fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), {}, float_diag)) << float_diag.format();
    g["scene"]["precision"] = "double";
    fg::Diagnostics diag;
    EXPECT_FALSE(fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), {}, diag));
    const std::string text = diag.format();
    EXPECT_NE(text.find("node 'soft'"), std::string::npos) << text;
    EXPECT_NE(text.find("tanh()"), std::string::npos) << text;
}

// Lowering keeps every line where it was, so a GLSL error in custom code still points at the node.
TEST(DoublePrecision, a_glsl_error_in_lowered_custom_code_names_the_node) {
    json g = fg::test::minimal_graph();
    g["nodes"].push_back(json::parse(R"({"id": "typo", "type": "custom.glsl",
        "ports": {"inputs": [{"name": "p", "type": "vec3", "default": "position"}],
                  "outputs": [{"name": "d", "type": "float"}]},
        "lipschitz": 1.0, "code": ["float r = length(p);", "d = lenght(p) - 0.5;"]})"));
    g["outputs"]["distance"] = "typo.d";
    g["scene"]["precision"] = "double";
    fg::Diagnostics diag;
    EXPECT_FALSE(fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), {}, diag));
    const std::string text = diag.format();
    EXPECT_NE(text.find("typo"), std::string::npos) << text;
    EXPECT_NE(text.find("lenght"), std::string::npos) << text;
    EXPECT_NE(text.find("line 2"), std::string::npos) << text;
}

TEST(DoublePrecision, packs_written_before_the_field_read_as_float) {
    fg::Diagnostics diag;
    auto result = fg::compile_graph(fg::test::minimal_graph().dump(), fg::NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(result) << diag.format();
    json m = json::parse(fg::manifest_to_json(result->manifest).dump());   // as a pack holds it
    m.erase("precision");
    auto read = fg::manifest_from_json(m, diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_EQ(read->precision, "float");
    m["precision"] = "half";
    fg::Diagnostics bad;
    EXPECT_FALSE(fg::manifest_from_json(m, bad));
    EXPECT_NE(bad.format().find("/precision"), std::string::npos);
}

}  // namespace
