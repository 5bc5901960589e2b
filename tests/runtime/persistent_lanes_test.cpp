// Persistent lanes change which lane marches a pixel, never what the pixel gets: frames are
// bit-identical with and without, in naive and per-eye marching, with and without the lens mask
// and foveation, at any burst share. And they keep the lanes busy: level 0's lane efficiency (busy
// lane-iterations over all, from subgroup ballots in the counting frame) rises in the filled view.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "frame/persistent_groups.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

struct Case {
    std::string graph;
    StereoMode stereo;
    bool fewer_pixels;
};

std::string name_of(const ::testing::TestParamInfo<Case>& info) {
    std::string g = info.param.graph.substr(info.param.graph.rfind('/') + 1);
    return fmt::format("{}_{}_{}", g, info.param.stereo == StereoMode::Naive ? "naive" : "per_eye",
                       info.param.fewer_pixels ? "mask_and_foveation" : "full");
}

class PersistentLanes : public RuntimeTest, public ::testing::WithParamInterface<Case> {};

RenderedFrame render(const Pack& pack, const Case& c, bool persistent, std::uint32_t size, bool count = false,
                     double lane_burst = 0.875, std::uint64_t launched = 0) {
    FrameSettings fs;
    fs.width = size;
    fs.height = size - 8;   // edge tiles of the queue's 8x8 order are partly outside
    fs.stereo = c.stereo;
    fs.lens_mask = c.fewer_pixels;
    fs.foveation = c.fewer_pixels ? 0.5 : 0.0;
    fs.count_evaluations = count;
    fs.knobs["persistent_lanes"] = persistent ? 1.0 : 0.0;
    fs.knobs["lane_burst"] = lane_burst;
    fs.persistent_invocations = launched;
    HeadlessRenderer r(test::shared_context(), pack, fs, StereoSettings{});
    return r.render(r.scene_camera(), 0.0);
}

}  // namespace

TEST_P(PersistentLanes, frames_are_bit_identical_with_and_without) {
    const Case& c = GetParam();
    Pack pack = test::compile_pack(test::read_source_file("graphs/" + c.graph + ".json"));
    RenderedFrame plain = render(pack, c, false, 72);
    RenderedFrame persistent = render(pack, c, true, 72);
    EXPECT_EQ(plain.depth_left, persistent.depth_left);
    EXPECT_EQ(plain.depth_right, persistent.depth_right);
    EXPECT_EQ(plain.left.pixels, persistent.left.pixels);
    EXPECT_EQ(plain.right.pixels, persistent.right.pixels);
    // Counting changes nothing either, and both count the same evaluations.
    RenderedFrame counted = render(pack, c, false, 72, true), counted_persistent = render(pack, c, true, 72, true);
    EXPECT_EQ(counted_persistent.depth_left, plain.depth_left);
    EXPECT_EQ(counted.stats.evaluations, counted_persistent.stats.evaluations);
    // However full a subgroup stays before its idle lanes refill (knob lane_burst, a GPU's lever).
    for (double burst : {0.5, 1.0}) {
        RenderedFrame b = render(pack, c, true, 72, false, burst);
        EXPECT_EQ(b.depth_left, plain.depth_left) << "lane_burst " << burst;
        EXPECT_EQ(b.right.pixels, plain.right.pixels) << "lane_burst " << burst;
    }
    // However many lanes the dispatch launches, as a GPU's fill does: twice the loop bound's count,
    // and a lane per pixel, where most groups find the queue dry.
    for (std::uint64_t launched : {std::uint64_t(600), std::uint64_t(1) << 20}) {
        RenderedFrame l = render(pack, c, true, 72, false, 0.875, launched);
        EXPECT_EQ(l.depth_left, plain.depth_left) << launched << " invocations";
        EXPECT_EQ(l.right.pixels, plain.right.pixels) << launched << " invocations";
    }
}

INSTANTIATE_TEST_SUITE_P(Gallery, PersistentLanes,
                         ::testing::Values(Case{"gallery/mandelbulb", StereoMode::Naive, false},
                                           Case{"gallery/mandelbulb", StereoMode::PerEye, false},
                                           Case{"gallery/mandelbulb", StereoMode::PerEye, true},
                                           Case{"gallery/mandelbox", StereoMode::Naive, true},
                                           Case{"gallery/kleinian", StereoMode::PerEye, false},
                                           Case{"gallery/julia_pool", StereoMode::PerEye, true},
                                           Case{"hard/deep_zoom", StereoMode::PerEye, false}),
                         name_of);

class LaneQueue : public RuntimeTest {};

// llvmpipe ends every loop of a shader invocation once all of them together ran 65535 iterations,
// and runs a dispatch's workgroups in order: at 72x64 each lane takes a few pixels, but at 256x248
// unbounded lanes of the first workgroups took most of the queue and were cut off mid-ray (56 of
// the bulb's pixels per eye never written). Each lane now takes at most FG_LANE_PIXELS.
TEST_F(LaneQueue, no_pixel_is_lost_when_the_first_workgroups_could_take_the_whole_queue) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    for (StereoMode stereo : {StereoMode::Naive, StereoMode::PerEye}) {
        SCOPED_TRACE(stereo_mode_name(stereo));
        Case c{"gallery/mandelbulb", stereo, false};
        RenderedFrame plain = render(pack, c, false, 256), persistent = render(pack, c, true, 256);
        EXPECT_TRUE(plain.depth_left == persistent.depth_left);
        EXPECT_TRUE(plain.depth_right == persistent.depth_right);
    }
}

class LaneEfficiency : public RuntimeTest {};

TEST_F(LaneEfficiency, persistent_lanes_keep_level_0_busy_in_the_filled_view) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameSettings fs;
    fs.width = fs.height = 128;
    fs.count_evaluations = true;
    StereoSettings stereo;
    // The filled view of the benchmark: close to the surface, the fractal in every pixel.
    HeadPose filled = look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    auto efficiency = [&](StereoMode mode, bool persistent) {
        FrameSettings s = fs;
        s.stereo = mode;
        s.knobs["persistent_lanes"] = persistent ? 1.0 : 0.0;
        HeadlessRenderer r(test::shared_context(), pack, s, stereo);
        FrameStats stats = r.render(filled, 0.0).stats;
        const char* group = mode == StereoMode::Naive ? "march" : "march.L0";
        EXPECT_TRUE(stats.lanes.count(group)) << "no lane counts for " << group;
        return stats.lanes[group].efficiency();
    };
    double cone = efficiency(StereoMode::PerEye, false), cone_persistent = efficiency(StereoMode::PerEye, true);
    double naive = efficiency(StereoMode::Naive, false), naive_persistent = efficiency(StereoMode::Naive, true);
    std::string figures = fmt::format("lane efficiency at 128x128, filled view: per-eye level 0 {:.3f} -> {:.3f} persistent; "
                                      "naive {:.3f} -> {:.3f}",
                                      cone, cone_persistent, naive, naive_persistent);
    RecordProperty("figures", figures);
    std::printf("%s\n", figures.c_str());
    EXPECT_GT(cone, 0.2);
    EXPECT_LT(cone, 0.85) << "without refills the slowest ray of a group keeps its lanes waiting";
    // 0.73 -> 0.88 for level 0, 0.84 -> 0.90 for naive, refilling once one lane in eight is idle
    // (knob lane_burst); the issue asks 0.85 of level 0. Refilling at three quarters gave 0.82.
    EXPECT_GE(cone_persistent, 0.85);
    EXPECT_GT(naive_persistent, naive + 0.03);
}

// A 512² eye's queue (262,144 indices) in workgroups of 64: the loop bound alone launched 256
// groups, 16,384 lanes, about 6 % of what an H100 runs at once (132 SMs x 64 warps x 32).
TEST(PersistentGroups, a_gpu_gets_as_many_lanes_as_it_runs_at_once) {
    const std::uint64_t eye_512 = 512 * 512, eye_1920 = 1920 * 1920, h100 = 132 * 64 * 32;
    EXPECT_EQ(persistent_group_count(eye_512, 64, persistent_fill(eye_512, true, 0, 0)), 256u) << "a CPU device";
    EXPECT_EQ(persistent_group_count(eye_512, 64, persistent_fill(eye_512, false, h100, 0)), 4096u)
        << "no more groups than give every lane an index";
    EXPECT_EQ(persistent_group_count(eye_1920, 64, persistent_fill(eye_1920, false, h100, 0)), 4224u)
        << "the device full";
    EXPECT_EQ(persistent_group_count(eye_1920, 64, persistent_fill(eye_1920, true, 0, 0)), 3600u)
        << "the loop bound: 16 pixels a lane on average";
    EXPECT_EQ(persistent_group_count(eye_512, 64, persistent_fill(eye_512, false, 0, 0)), 1024u)
        << "a GPU that does not say: four pixels a lane";
    EXPECT_EQ(persistent_group_count(eye_512, 64, persistent_fill(eye_512, true, 0, 6400)), 256u)
        << "a request below the loop bound's count does not lower it";
    EXPECT_EQ(persistent_group_count(eye_512, 64, persistent_fill(eye_512, true, 0, 64000)), 1000u) << "a request";
}
