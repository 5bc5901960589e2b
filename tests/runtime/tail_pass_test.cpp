// The tail pass (knob tail_after) moves the full-resolution march of slow pixels into compact
// workgroups after that many steps; it changes which lane marches a pixel, never what the pixel
// gets: depth and colour are bit-identical with and without, and the evaluations are the same.
#include <gtest/gtest.h>

#include "runtime_test_support.h"

using namespace fg;
using fg::test::RuntimeTest;

namespace {

class TailPass : public RuntimeTest {};

RenderedFrame render(const Pack& pack, int tail_after, bool fewer_pixels) {
    FrameSettings fs;
    fs.width = 72;
    fs.height = 64;
    fs.stereo = StereoMode::PerEye;
    fs.lens_mask = fewer_pixels;
    fs.foveation = fewer_pixels ? 0.5 : 0.0;
    fs.count_evaluations = true;
    fs.knobs["tail_after"] = tail_after;
    HeadlessRenderer r(test::shared_context(), pack, fs, StereoSettings{});
    // The filled view of the benchmark: most rays need more than a few steps near the surface.
    return r.render(look_at({0.0, 0.55, 1.45}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), 0.0);
}

}  // namespace

TEST_F(TailPass, frames_are_bit_identical_with_and_without) {
    Pack pack = test::compile_pack(test::read_source_file("graphs/gallery/mandelbulb.json"));
    for (bool fewer_pixels : {false, true}) {
        SCOPED_TRACE(fewer_pixels ? "lens mask and foveation" : "every pixel");
        RenderedFrame plain = render(pack, 0, fewer_pixels);
        RenderedFrame tail = render(pack, 6, fewer_pixels);
        ASSERT_TRUE(tail.stats.evaluations.count("tail")) << "no tail pass in the frame";
        EXPECT_GT(tail.stats.evaluations.at("tail"), 0u) << "the tail pass marched nothing";
        EXPECT_EQ(plain.depth_left, tail.depth_left);
        EXPECT_EQ(plain.depth_right, tail.depth_right);
        EXPECT_EQ(plain.left.pixels, tail.left.pixels);
        EXPECT_EQ(plain.right.pixels, tail.right.pixels);
        EXPECT_EQ(plain.stats.evaluations_per_pixel, tail.stats.evaluations_per_pixel);   // all groups together
    }
}
