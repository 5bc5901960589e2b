// The frame graph holds only what the pack's effects need: checked on its description, and by
// running it.
#include <gtest/gtest.h>

#include <functional>

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

// An image of the eye's size whose name starts with prefix (the one-pixel stand-ins of knobs that
// are off do not count).
bool has_full_image(const FrameGraph& g, const std::string& prefix) {
    for (const auto& i : g.images())
        if (i.name.rfind(prefix, 0) == 0 && i.width > 1) return true;
    return false;
}

const FramePass& pass_labelled(const FrameGraph& g, const std::string& label) {
    for (const auto& p : g.passes())
        if (p.label == label) return p;
    throw std::runtime_error("no pass " + label + " in\n" + g.describe());
}

std::size_t passes_of(const FrameGraph& g, const std::string& program) {
    std::size_t n = 0;
    for (const auto& p : g.passes()) n += p.program == program;
    return n;
}

}  // namespace

TEST(FrameGraph, a_pack_without_fog_or_glow_allocates_no_glow_image_and_no_colour_before_post) {
    Pack pack = test::compile_pack(graph_with_scene("{}"));
    for (auto mode : {StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject}) {
        FrameGraph g = graph_for(pack, mode);
        EXPECT_FALSE(has_image(g, "glow.")) << g.describe();
        EXPECT_FALSE(has_full_image(g, "color.")) << g.describe();
        EXPECT_TRUE(pass_labelled(g, "shade.left").writes_resource("final.left"));
    }
}

// Fog is a function of each pixel's colour and depth: the shade pass applies it on its way to the
// final image, with no pass and no HDR image of its own.
TEST(FrameGraph, fog_is_applied_by_the_shade_pass_on_its_way_to_the_final_image) {
    Pack pack = test::compile_pack(graph_with_scene(R"({"fog": {"density": 0.3}})"));
    FrameGraph g = graph_for(pack, StereoMode::PerEye);
    EXPECT_EQ(g.passes().back().program, "shade") << g.describe();
    EXPECT_TRUE(pass_labelled(g, "shade.right").writes_resource("final.right"));
    EXPECT_FALSE(has_full_image(g, "color.")) << g.describe();
    EXPECT_FALSE(has_image(g, "glow.")) << g.describe();
}

TEST(FrameGraph, glow_adds_glow_images_written_by_the_march_and_read_by_shade) {
    Pack pack = test::compile_pack(graph_with_scene(R"({"glow": {"intensity": 0.5}})"));
    FrameGraph g = graph_for(pack, StereoMode::Reproject);
    EXPECT_TRUE(has_image(g, "glow.centre")) << g.describe();
    EXPECT_TRUE(has_image(g, "glow.left"));
    EXPECT_TRUE(pass_labelled(g, "shade.left").reads_resource("glow.left"));
    EXPECT_TRUE(pass_labelled(g, "shade.right").reads_resource("glow.right"));
}

// A pack from an fgc before post effects moved into the shade pass has a post pass that this frame
// graph cannot bind: it is refused with the way out, not run into a wrong picture.
TEST(FrameGraph, a_pack_with_a_separate_post_pass_is_refused_with_a_request_to_recompile) {
    Pack pack = test::compile_pack(graph_with_scene(R"({"fog": {"density": 0.3}})"));
    ManifestPass post = *pack.manifest.find_pass("shade");
    post.name = "post";
    pack.manifest.passes.push_back(post);
    try {
        graph_for(pack, StereoMode::PerEye);
        FAIL() << "a pack with a post pass was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("recompile"), std::string::npos) << e.what();
    }
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

// A shader that declares an image in another format than the frame graph allocates would read and
// write garbage (shading reuse's images changed from rgba16f to rgba32ui): the executor compares each
// storage image's declared format, which the pack records, and refuses a pack that records none.
TEST_F(FrameGraphRun, an_image_in_another_format_than_its_shader_declares_is_refused) {
    FrameSettings s;
    s.width = s.height = 32;
    auto refusal = [&](const std::function<void(ManifestBinding&)>& edit) {
        Pack pack = test::compile_pack(graph_with_scene("{}"));
        for (auto& p : pack.manifest.passes)
            for (auto& b : p.bindings)
                if (p.name == "shade" && b.name == "fg_final") edit(b);
        try {
            HeadlessRenderer r(test::shared_context(), pack, s, {});
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal([](ManifestBinding&) {}), "accepted");
    EXPECT_NE(refusal([](ManifestBinding& b) { b.format = "rgba16f"; })
                  .find("binds final.left (rgba8) to 'fg_final', which its shader declares rgba16f: recompile"),
              std::string::npos);
    EXPECT_NE(refusal([](ManifestBinding& b) { b.format.clear(); }).find("compiled by an older fgc; recompile"),
              std::string::npos);
}
