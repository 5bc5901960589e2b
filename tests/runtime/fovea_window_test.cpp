// A foveated eye's full-resolution passes dispatch only a window around the fovea
// (FrameGraph::fovea_window, fg_dispatch_cell in common.glsl), and its conemarch level 1 the same
// window at half resolution: the pixels beyond belong to the periphery's dispatch, whose pixels
// start from level 2, and a CPU rasteriser runs a whole shader for a SIMD group whose lanes have
// nothing to do. Frames must be bit-identical to a dispatch over the whole image, also for a
// headset's off-centre lenses, where the window follows the lens centre.
#include <gtest/gtest.h>

#include "frame/frame_executor.h"
#include "frame/gpu_uniforms.h"
#include "runtime_test_support.h"

using namespace fg;
using fg::test::pass_named;
using fg::test::RuntimeTest;

namespace {

class FoveaWindow : public RuntimeTest {};

constexpr std::uint32_t kWidth = 160, kHeight = 120;

FrameSettings foveated(StereoMode stereo, bool window) {
    FrameSettings fs;
    fs.width = kWidth;
    fs.height = kHeight;
    fs.stereo = stereo;
    fs.lens_mask = true;
    fs.foveation = 0.4;
    fs.fovea_window = window;
    fs.count_evaluations = true;
    return fs;
}

struct Frame {
    std::vector<std::byte> left, right, depth_left, depth_right;
    double evaluations_per_pixel = 0.0;
};

// Both eyes through lenses whose centres sit off the image centre, as a headset's do (the
// left lens's towards the nose: the image's right).
Frame render(const Pack& pack, const FrameSettings& fs) {
    StereoSettings stereo;
    stereo.width = fs.width;
    stereo.height = fs.height;
    Fov left{-1.05, 0.8, -0.95, 0.7}, right{-0.8, 1.05, -0.95, 0.7};
    StereoViews views = make_stereo_views(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}), left, right, stereo);
    FrameExecutor executor(test::shared_context(), pack,
                           FrameGraph::build(pack.manifest, fs, views.centre.width, views.centre.height));
    executor.set_frame(make_gpu_frame(views, executor.graph().settings, 0.0, 1.0, 0));
    Frame f;
    f.evaluations_per_pixel = executor.run().evaluations_per_pixel;
    f.left = executor.download("final.left");
    f.right = executor.download("final.right");
    f.depth_left = executor.download("depth.left");
    f.depth_right = executor.download("depth.right");
    return f;
}

}  // namespace

TEST_F(FoveaWindow, the_full_resolution_dispatches_cover_the_fovea_and_the_periphery_the_image) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    FrameGraph g = FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, true), kWidth, kHeight);
    // Fovea 0.4 and blend 0.15 half heights: 33 pixels around the centre, 8.5 + 2 of slack, whole 8s.
    for (const char* label : {"conemarch.left.L0", "shade.left", "conemarch.right.L0", "shade.right"}) {
        SCOPED_TRACE(label);
        EXPECT_EQ(pass_named(g, label).invocations, (std::array<std::uint32_t, 3>{96, 96, 1}));
    }
    EXPECT_EQ(pass_named(g, "conemarch.left.L0.periphery").invocations, (std::array<std::uint32_t, 3>{80, 60, 1}));
    // Level 1 serves only the pixels short of the periphery: the same window at half resolution.
    // The periphery's pixels start from level 2.
    EXPECT_EQ(pass_named(g, "conemarch.left.L1").invocations, (std::array<std::uint32_t, 3>{48, 48, 1}));
    EXPECT_EQ(pass_named(g, "conemarch.left.L0.periphery").specialize.at(kSpecPeripheryParent.id), 2);
    FrameSettings reuse = foveated(StereoMode::PerEye, true);
    reuse.knobs["reuse"] = 1.0;   // walks every cell of the old level 1: it is marched whole, and the periphery starts there
    FrameGraph with_reuse = FrameGraph::build(pack.manifest, reuse, kWidth, kHeight);
    EXPECT_EQ(pass_named(with_reuse, "conemarch.left.L1").invocations, (std::array<std::uint32_t, 3>{80, 60, 1}));
    EXPECT_FALSE(pass_named(with_reuse, "conemarch.left.L0.periphery").specialize.count(kSpecPeripheryParent.id));
    FrameGraph whole = FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, false), kWidth, kHeight);
    EXPECT_EQ(pass_named(whole, "shade.left").invocations, (std::array<std::uint32_t, 3>{kWidth, kHeight, 1}));
    // A fovea wider than the image: the window is the image.
    FrameSettings wide = foveated(StereoMode::PerEye, true);
    wide.foveation = 1.5;
    EXPECT_EQ(pass_named(FrameGraph::build(pack.manifest, wide, kWidth, kHeight), "shade.left").invocations,
              (std::array<std::uint32_t, 3>{kWidth, kHeight, 1}));
    // A pack whose shaders cannot place the window (an older fgc's) dispatches the whole image.
    for (auto& pass : pack.manifest.passes) std::erase(pass.dispatch_constants, kSpecFoveaWindow.id);
    EXPECT_EQ(pass_named(FrameGraph::build(pack.manifest, foveated(StereoMode::PerEye, true), kWidth, kHeight),
                         "shade.left")
                  .invocations,
              (std::array<std::uint32_t, 3>{kWidth, kHeight, 1}));
}

TEST_F(FoveaWindow, frames_are_bit_identical_to_a_dispatch_over_the_whole_image) {
    // The bulb shades straight into the final image; the KIFS's glow adds the post pass.
    for (const char* graph : {"graphs/gallery/mandelbulb.json", "graphs/gallery/kifs.json"}) {
        Pack pack = test::compile_pack(test::read_source_file(graph));
        for (StereoMode stereo : {StereoMode::Naive, StereoMode::PerEye, StereoMode::Reproject}) {
            SCOPED_TRACE(std::string(graph) + " " + stereo_mode_name(stereo));
            Frame window = render(pack, foveated(stereo, true));
            Frame whole = render(pack, foveated(stereo, false));
            EXPECT_TRUE(window.left == whole.left);
            EXPECT_TRUE(window.right == whole.right);
            EXPECT_TRUE(window.depth_left == whole.depth_left);
            EXPECT_TRUE(window.depth_right == whole.depth_right);
            // The same rays; per-eye, level 1 no longer marches the periphery's cells, which no pixel reads.
            if (stereo == StereoMode::PerEye) EXPECT_LT(window.evaluations_per_pixel, whole.evaluations_per_pixel);
            else EXPECT_EQ(window.evaluations_per_pixel, whole.evaluations_per_pixel);
        }
    }
}
