// The frame graph's declarations do the work: they order the passes into batches with a barrier
// only where a hazard exists, every binding is checked against what its shader does with it, a
// push constant of the wrong size is refused, a name cannot mean two images, and a history image
// carries a frame's contents into the next. A graph that lies about a read is caught before it
// runs (the validation layer of Debian 12 does not track dispatch-to-dispatch hazards).
#include <gtest/gtest.h>

#include <algorithm>
#include <fmt/format.h>

#include "frame/frame_executor.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::pass_named;

namespace {

const char* kBall = R"({"format": "fractograph-graph", "version": 1, "name": "ball",
  "nodes": [{"id": "ball", "type": "prim.sphere"}], "outputs": {"distance": "ball"},
  "scene": {"camera": {"position": [0, 0, 3], "target": [0, 0, 0]}, "glow": {"intensity": 0.3}}})";

FrameGraph build(const Pack& pack, StereoMode mode, std::uint32_t levels = 4, double foveation = 0.0) {
    FrameSettings s;
    s.width = 40;
    s.height = 32;
    s.stereo = mode;
    s.cone_levels = levels;
    s.foveation = foveation;
    return FrameGraph::build(pack.manifest, s, 48, 32);
}

std::size_t batch_of(const FrameGraph& g, const std::string& label) {
    auto batches = g.batches();
    for (std::size_t b = 0; b < batches.size(); ++b)
        for (std::size_t i : batches[b])
            if (g.passes()[i].label == label) return b;
    ADD_FAILURE() << "no pass " << label << " in\n" << g.describe();
    return 0;
}

class FrameGraphDeclarations : public test::RuntimeTest {};

}  // namespace

TEST(FrameGraphBatches, the_two_eyes_march_side_by_side_and_each_pass_follows_what_it_reads) {
    Pack pack = test::compile_pack(kBall);
    FrameGraph g = build(pack, StereoMode::PerEye);
    for (int k = 3; k >= 0; --k)
        EXPECT_EQ(batch_of(g, fmt::format("conemarch.left.L{}", k)), batch_of(g, fmt::format("conemarch.right.L{}", k)))
            << g.describe();
    EXPECT_LT(batch_of(g, "conemarch.left.L1"), batch_of(g, "conemarch.left.L0"));
    EXPECT_LT(batch_of(g, "conemarch.left.L0"), batch_of(g, "shade.left"));
    // 4 levels and shade (glow included): 5 batches, 4 barriers (one per pass and eye before: 9).
    EXPECT_EQ(g.batches().size(), 5u) << g.describe();
    EXPECT_NE(g.describe().find("4 barriers"), std::string::npos) << g.describe();
}

TEST(FrameGraphBatches, reprojection_waits_for_the_centre_eye_and_the_foveated_periphery_for_its_full_dispatch) {
    Pack pack = test::compile_pack(kBall);
    FrameGraph r = build(pack, StereoMode::Reproject);
    EXPECT_LT(batch_of(r, "conemarch.centre.L0"), batch_of(r, "reproject.left"));
    EXPECT_EQ(batch_of(r, "reproject.left"), batch_of(r, "reproject.right"));
    FrameGraph f = build(pack, StereoMode::PerEye, 4, 0.4);
    // Both dispatches write the depth image (disjoint pixels, but declared as one image).
    EXPECT_LT(batch_of(f, "conemarch.left.L0"), batch_of(f, "conemarch.left.L0.periphery"));
    EXPECT_LT(batch_of(f, "shade.left.periphery"), batch_of(f, "fovea.left"));
}

TEST(FrameGraphBatches, a_pass_that_overwrites_what_another_reads_waits_for_the_reader) {
    FrameGraph g;
    auto pass = [&](const char* label, std::vector<std::string> reads, std::vector<std::string> writes) {
        FramePass p;
        p.label = label;
        for (auto& r : reads) p.bind(r, r, Access::Read);
        for (auto& w : writes) p.bind(w, w, Access::Write);
        g.add_pass(p);
    };
    pass("a", {}, {"x"});
    pass("b", {"x"}, {"y"});
    pass("c", {}, {"x"});   // write after b's read
    pass("d", {}, {"z"});   // independent of all
    EXPECT_EQ(batch_of(g, "a"), 0u);
    EXPECT_EQ(batch_of(g, "b"), 1u);
    EXPECT_EQ(batch_of(g, "c"), 2u);
    EXPECT_EQ(batch_of(g, "d"), 0u);
}

TEST(FrameGraphImages, one_name_for_two_different_images_is_an_error) {
    FrameGraph g;
    g.add_image({"depth.left", 64, 64, ImageFormat::R32F, "a"});
    EXPECT_NO_THROW(g.add_image({"depth.left", 64, 64, ImageFormat::R32F, "the same image again"}));
    EXPECT_THROW(g.add_image({"depth.left", 32, 64, ImageFormat::R32F, "another size"}), std::logic_error);
    EXPECT_THROW(g.add_image({"depth.left", 64, 64, ImageFormat::RG32F, "another format"}), std::logic_error);
}

TEST_F(FrameGraphDeclarations, a_pass_that_does_not_declare_a_read_its_shader_does_is_refused) {
    Pack pack = test::compile_pack(kBall);
    FrameGraph g = build(pack, StereoMode::PerEye);
    auto& reads = pass_named(g, "shade.left").reads;
    reads.erase(std::find(reads.begin(), reads.end(), "depth.left"));
    try {
        FrameExecutor e(test::shared_context(), pack, std::move(g));
        FAIL() << "a graph with an undeclared read ran";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("pass shade.left binds depth.left to 'fg_depth', which its shader reads"),
                  std::string::npos)
            << e.what();
    }
}

TEST_F(FrameGraphDeclarations, a_push_constant_of_another_size_than_the_shaders_is_refused_not_padded) {
    Pack pack = test::compile_pack(kBall);
    FrameGraph g = build(pack, StereoMode::Naive);
    pass_named(g, "naive.left").push.resize(8);
    try {
        FrameExecutor e(test::shared_context(), pack, std::move(g));
        FAIL() << "a short push constant was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("pass naive.left pushes 8 bytes of constants, and its shader's block is 12"),
                  std::string::npos)
            << e.what();
    }
}

TEST_F(FrameGraphDeclarations, a_history_image_holds_the_previous_frame) {
    Pack pack = test::compile_pack(kBall);
    FrameGraph g = build(pack, StereoMode::Naive);
    g.keep_for_next_frame("depth.left");
    FrameSettings s = g.settings;
    HeadlessRenderer renderer(test::shared_context(), pack, s, {});
    FrameExecutor e(test::shared_context(), pack, std::move(g));
    auto frame_at = [&](double x) {
        HeadPose head = look_at({x, 0.0, 3.0}, {x, 0.0, 0.0}, {0.0, 1.0, 0.0});
        renderer.render(head, 0.0);   // only for its views
        e.set_frame(make_gpu_frame(renderer.views(), e.graph().settings, 0.0, 1.0, 0));
        e.run();
        return e.download("depth.left");
    };
    auto first = frame_at(0.0);
    auto second = frame_at(0.5);
    EXPECT_NE(first, second) << "the head moved: the depth should change";
    EXPECT_EQ(e.download("depth.left.previous"), first);
    auto third = frame_at(-0.5);
    EXPECT_EQ(e.download("depth.left.previous"), second);
    EXPECT_EQ(e.download("depth.left"), third);
}

// The validation layer with synchronization checks on, over every stereo mode, foveation, the
// tail pass and history images, for several frames: the derived barriers leave nothing for it to
// report (what it tracks: copies, downloads, layout transitions, frame to frame).
TEST(FrameGraphSynchronization, derived_barriers_leave_the_synchronization_validation_nothing_to_report) {
    vk::ContextOptions o;
    o.validation = true;
    o.synchronization_validation = true;
    vk::Context ctx(o);
    Pack pack = test::compile_pack(kBall);
    struct Variant {
        StereoMode mode;
        double foveation;
        std::map<std::string, double> knobs;
    };
    for (const Variant& v : {Variant{StereoMode::Naive, 0.0, {}}, Variant{StereoMode::PerEye, 0.4, {{"tail_after", 4}}},
                             Variant{StereoMode::Reproject, 0.4, {{"shade_reuse", 1}}}}) {
        FrameSettings s;
        s.width = 40;
        s.height = 32;
        s.stereo = v.mode;
        s.foveation = v.foveation;
        s.knobs = v.knobs;
        HeadlessRenderer r(ctx, pack, s, {});
        for (int frame = 0; frame < 3; ++frame) r.render(look_at({0.1 * frame, 0.0, 3.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), 0.0);
    }
    EXPECT_EQ(ctx.validation_errors(), 0u) << [&] {
        std::string all;
        for (const auto& m : ctx.validation_messages()) all += m + "\n";
        return all;
    }();
}
