// The scene settings are decoded once, typed: the locomotion block is checked like every other
// block (a typo is an error naming its pointer, not a setting silently ignored), and a pack's
// manifest carries the settings the compiler decoded, readable in packs written before.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "graph/scene_settings.h"
#include "pack/manifest.h"
#include "test_support.h"

namespace {

using fg::test::check_front;
using fg::test::has_error;
using fg::test::minimal_graph;
using nlohmann::json;

TEST(SceneSettings, a_misspelled_locomotion_field_is_refused_with_its_pointer) {
    auto g = minimal_graph();
    g["scene"]["locomotion"] = {{"max_sped", 3.0}};
    EXPECT_TRUE(has_error(check_front(g), "/scene/locomotion/max_sped", "",
                          "unknown scene setting \"max_sped\"; did you mean \"max_speed\"?"));
}

TEST(SceneSettings, a_locomotion_limit_must_be_a_positive_number) {
    auto g = minimal_graph();
    g["scene"]["locomotion"] = {{"max_speed", "fast"}, {"head_radius", 0.0}, {"speed_per_distance", -1.0}};
    auto diag = check_front(g);
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/max_speed", "", "expected a number, got a string"));
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/head_radius", "", "0 is out of range (0, inf]"));
    EXPECT_TRUE(has_error(diag, "/scene/locomotion/speed_per_distance", "", "-1 is out of range (0, inf]"));
    g["scene"]["locomotion"] = 2.0;
    EXPECT_TRUE(has_error(check_front(g), "/scene/locomotion", "", "expected an object, got a number"));
}

TEST(SceneSettings, locomotion_limits_reach_the_manifest_typed) {
    auto g = minimal_graph();
    g["scene"]["locomotion"] = {{"max_speed", 3.5}, {"head_radius", 0.02}};
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    const fg::LocomotionSettings& loco = r->manifest.scene.locomotion;
    EXPECT_EQ(loco.max_speed, 3.5);
    EXPECT_EQ(loco.head_radius, 0.02);
    EXPECT_EQ(loco.speed_per_distance, fg::LocomotionSettings{}.speed_per_distance);
}

// The default light, for a graph without a light block, is as unit-length as a given one: the
// shade pass takes dot(n, direction) as Lambert's cosine.
TEST(SceneSettings, a_graph_without_a_light_is_lit_from_a_unit_direction) {
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(minimal_graph().dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_NEAR(glm::length(r->manifest.scene.light.direction), 1.0, 1e-15);
}

TEST(SceneSettings, an_auxiliary_light_is_a_point_or_a_direction_and_there_are_at_most_four) {
    auto g = minimal_graph();
    json both = {{"position", {0, 1, 0}}, {"direction", {0, 1, 0}}};
    g["scene"]["light"]["auxiliary"] = {both, {{"color", 1.0}}, {{"positon", {0, 1, 0}}}};
    auto diag = check_front(g);
    const std::string either = "a light has either a position (a point light) or a direction (a directional light)";
    EXPECT_TRUE(has_error(diag, "/scene/light/auxiliary/0", "", either)) << diag.format();
    EXPECT_TRUE(has_error(diag, "/scene/light/auxiliary/1", "", either)) << diag.format();
    EXPECT_TRUE(has_error(diag, "/scene/light/auxiliary/2/positon", "", "did you mean \"position\"?")) << diag.format();
    g["scene"]["light"]["auxiliary"] = json::array();
    for (int i = 0; i < 5; ++i) g["scene"]["light"]["auxiliary"].push_back({{"direction", {0, 1, 0}}});
    EXPECT_TRUE(has_error(check_front(g), "/scene/light/auxiliary", "", "at most 4 auxiliary lights"));
}

TEST(SceneSettings, auxiliary_lights_reach_the_manifest_and_read_back) {
    auto g = minimal_graph();
    g["scene"]["light"]["auxiliary"] = {{{"position", {1, 2, 3}}, {"color", {4, 5, 6}}}, {{"direction", {0, 2, 0}}}};
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    const auto& lights = r->manifest.scene.light.auxiliary;
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_EQ(lights[0].position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(lights[0].color, glm::dvec3(4, 5, 6));
    EXPECT_FALSE(lights[1].position);
    EXPECT_EQ(lights[1].direction, glm::dvec3(0, 1, 0));
    auto read = fg::manifest_from_json(json::parse(fg::manifest_to_json(r->manifest).dump()), diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_TRUE(read->scene == r->manifest.scene);
    EXPECT_TRUE(r->manifest.effects.has(fg::Effect::Lights));
}

// What the compiler encodes, the pack reader decodes to the very same settings (the light direction
// is not normalised a second time), so the runtime sees what the compiler saw.
TEST(SceneSettings, what_the_compiler_encodes_decodes_to_the_same_settings) {
    auto graphs = fg::test::graph_files("graphs/gallery");
    for (const auto& hard : fg::test::graph_files("graphs/hard")) graphs.push_back(hard);
    ASSERT_GT(graphs.size(), 10u);
    for (const auto& graph : graphs) {
        fg::Diagnostics diag;
        std::ifstream in(graph);
        std::stringstream text;
        text << in.rdbuf();
        auto ir = fg::load_and_lower(text.str(), fg::NodeLibrary::builtin(), diag);
        ASSERT_TRUE(ir) << graph << ": " << diag.format();
        // As a pack holds it: JSON text.
        const json encoded = json::parse(fg::scene_settings_to_json(ir->scene).dump());
        EXPECT_TRUE(fg::parse_scene_settings(&encoded, "/scene", diag) == ir->scene) << graph;
        EXPECT_FALSE(diag.has_errors()) << diag.format();
    }
}

TEST(SceneSettings, a_compiled_manifest_reads_back_with_the_same_settings) {
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(fg::test::read_source_file("graphs/gallery/mandelbulb.json"), diag);
    ASSERT_TRUE(r) << diag.format();
    auto read = fg::manifest_from_json(json::parse(fg::manifest_to_json(r->manifest).dump()), diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_TRUE(read->scene == r->manifest.scene);
}

// Packs written before the block was typed hold "locomotion": {} (or some of its fields), and no
// precision unless it was double.
TEST(SceneSettings, packs_written_before_still_read) {
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(minimal_graph().dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    json m = fg::manifest_to_json(r->manifest);
    m["scene"]["locomotion"] = json::object();
    auto read = fg::manifest_from_json(m, diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_TRUE(read->scene.locomotion == fg::LocomotionSettings{});
    m["scene"]["locomotion"] = {{"max_speed", 4.0}};
    read = fg::manifest_from_json(m, diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_EQ(read->scene.locomotion.max_speed, 4.0);

    m["scene"]["locomotion"] = {{"max_sped", 4.0}};
    fg::Diagnostics bad;
    EXPECT_FALSE(fg::manifest_from_json(m, bad));
    EXPECT_TRUE(has_error(bad, "/manifest/scene/locomotion/max_sped", "", "unknown scene setting")) << bad.format();
}

TEST(SceneSettings, each_parse_is_counted) {
    const auto before = fg::scene_settings_parse_count();
    fg::Diagnostics diag;
    json scene = {{"exposure", 1.5}};
    fg::parse_scene_settings(&scene, "/scene", diag);
    EXPECT_EQ(fg::scene_settings_parse_count(), before + 1);
}

}  // namespace

TEST(SceneSettings, an_environment_is_a_uniform_sky_or_an_image_that_must_exist) {
    auto g = minimal_graph();
    g["scene"]["light"] = {{"direction", {0, 1, 0}}};
    g["scene"]["environment"] = {{"color", {0.5, 0.6, 0.7}}, {"intensity", 2.0}, {"rotation_deg", 30.0}};
    fg::Diagnostics diag;
    auto r = fg::test::compile_text(g.dump(), diag);
    ASSERT_TRUE(r) << diag.format();
    EXPECT_TRUE(r->manifest.effects.has(fg::Effect::Environment));
    EXPECT_FALSE(r->environment) << "a uniform sky carries no image";
    ASSERT_TRUE(r->manifest.scene.environment);
    EXPECT_EQ(r->manifest.scene.environment->rotation_deg, 30.0);
    auto read = fg::manifest_from_json(json::parse(fg::manifest_to_json(r->manifest).dump()), diag);
    ASSERT_TRUE(read) << diag.format();
    EXPECT_TRUE(read->scene == r->manifest.scene);

    g["scene"]["environment"] = {{"image", "no_such_sky.exr"}, {"intensty", 1.0}};
    diag = fg::Diagnostics();
    EXPECT_FALSE(fg::test::compile_text(g.dump(), diag));
    EXPECT_TRUE(has_error(diag, "/scene/environment/intensty", "", "did you mean \"intensity\"?")) << diag.format();
    g["scene"]["environment"].erase("intensty");
    diag = fg::Diagnostics();
    EXPECT_FALSE(fg::test::compile_text(g.dump(), diag));
    EXPECT_TRUE(has_error(diag, "/scene/environment/image", "", "cannot use 'no_such_sky.exr'")) << diag.format();

    // A server's compile (the studio's) reads no file outside its folder.
    fg::CompileOptions confined;
    confined.folder = "/tmp";
    confined.folder_confined = true;
    for (const char* outside : {"../etc/sky.exr", "/etc/sky.exr", "a/../../sky.exr"}) {
        g["scene"]["environment"]["image"] = outside;
        diag = fg::Diagnostics();
        EXPECT_FALSE(fg::compile_graph(g.dump(), fg::NodeLibrary::builtin(), confined, diag));
        EXPECT_TRUE(has_error(diag, "/scene/environment/image", "", "is outside the graph's folder")) << outside << diag.format();
    }
}
