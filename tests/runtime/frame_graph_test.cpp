// The frame graph holds only what the pack's effects need: checked on its description, and by
// running it.
#include <gtest/gtest.h>

#include "frame/frame_graph.h"
#include "runtime_test_support.h"

using namespace fg;

namespace {

std::string graph_with_scene(const std::string& scene) {
    return R"({"format": "fractograph-graph", "version": 1, "name": "s",
      "nodes": [{"id": "ball", "type": "prim.sphere"}], "outputs": {"distance": "ball"}, "scene": )" + scene + "}";
}

FrameGraph graph_for(const Pack& pack, StereoMode mode) {
    FrameSettings s;
    s.width = s.height = 64;
    s.stereo = mode;
    return FrameGraph::build(pack.manifest, s, 80, 64);
}

bool has_image(const FrameGraph& g, const std::string& prefix) {
    for (const auto& i : g.images())
        if (i.name.rfind(prefix, 0) == 0) return true;
    return false;
}

std::size_t passes_of(const FrameGraph& g, const std::string& program) {
    std::size_t n = 0;
    for (const auto& p : g.passes()) n += p.program == program;
    return n;
}

}  // namespace

TEST(FrameGraph, a_pack_without_fog_or_glow_allocates_no_glow_image_and_runs_no_post_pass) {
    Pack pack = test::compile_pack(graph_with_scene("{}"));
    for (auto mode : {StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject}) {
        FrameGraph g = graph_for(pack, mode);
        EXPECT_FALSE(has_image(g, "glow.")) << g.describe();
        EXPECT_FALSE(has_image(g, "color.")) << g.describe();
        EXPECT_EQ(passes_of(g, "post"), 0u) << g.describe();
        EXPECT_EQ(g.describe().find("post."), std::string::npos);
    }
}

TEST(FrameGraph, fog_adds_a_post_pass_per_eye_but_no_glow_image) {
    Pack pack = test::compile_pack(graph_with_scene(R"({"fog": {"density": 0.3}})"));
    FrameGraph g = graph_for(pack, StereoMode::PerEye);
    EXPECT_EQ(passes_of(g, "post"), 2u) << g.describe();
    EXPECT_TRUE(has_image(g, "color.left"));
    EXPECT_FALSE(has_image(g, "glow.")) << g.describe();
}

TEST(FrameGraph, glow_adds_glow_images_written_by_the_march_and_read_by_post) {
    Pack pack = test::compile_pack(graph_with_scene(R"({"glow": {"intensity": 0.5}})"));
    FrameGraph g = graph_for(pack, StereoMode::Reproject);
    EXPECT_TRUE(has_image(g, "glow.centre")) << g.describe();
    EXPECT_TRUE(has_image(g, "glow.left"));
    EXPECT_EQ(passes_of(g, "post"), 2u);
}

TEST(FrameGraph, stereo_modes_run_their_own_passes) {
    Pack pack = test::compile_pack(graph_with_scene("{}"));
    FrameSettings s;
    s.width = s.height = 64;
    s.cone_levels = 4;
    s.stereo = StereoMode::Naive;
    FrameGraph naive = FrameGraph::build(pack.manifest, s, 80, 64);
    EXPECT_EQ(passes_of(naive, "naive"), 2u);
    EXPECT_EQ(passes_of(naive, "conemarch"), 0u);
    s.stereo = StereoMode::PerEye;
    FrameGraph per_eye = FrameGraph::build(pack.manifest, s, 80, 64);
    EXPECT_EQ(passes_of(per_eye, "conemarch"), 8u);   // 4 levels x 2 eyes
    EXPECT_EQ(passes_of(per_eye, "reproject"), 0u);
    s.stereo = StereoMode::Reproject;
    FrameGraph reproject = FrameGraph::build(pack.manifest, s, 80, 64);
    EXPECT_EQ(passes_of(reproject, "conemarch"), 4u);  // the centre eye only
    EXPECT_EQ(passes_of(reproject, "reproject"), 2u);
    EXPECT_TRUE(has_image(reproject, "cone.centre"));
    EXPECT_FALSE(has_image(reproject, "cone.left"));
}

class FrameGraphRun : public test::RuntimeTest {};

TEST_F(FrameGraphRun, a_fog_and_glow_scene_renders_and_fog_changes_the_image) {
    auto render = [](const std::string& scene) {
        Pack pack = test::compile_pack(graph_with_scene(scene));
        FrameSettings s;
        s.width = s.height = 64;
        HeadlessRenderer r(test::shared_context(), pack, s, {});
        return r.render(r.scene_camera(), 0.0).left.pixels;
    };
    auto plain = render("{}");
    auto foggy = render(R"({"fog": {"density": 0.5, "color": [0.9, 0.9, 0.9]}, "glow": {"intensity": 0.3}})");
    EXPECT_NE(plain, foggy);
}

TEST_F(FrameGraphRun, an_unknown_knob_is_refused_with_the_list_of_knobs) {
    Pack pack = test::compile_pack(graph_with_scene("{}"));
    FrameSettings s;
    s.width = s.height = 32;
    s.knobs["epsilonn"] = 0.1;
    try {
        HeadlessRenderer r(test::shared_context(), pack, s, {});
        FAIL() << "accepted an unknown knob";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("unknown knob \"epsilonn\"; this pack's knobs are: epsilon"),
                  std::string::npos)
            << e.what();
    }
}
