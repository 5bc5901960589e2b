// fgplay's commands read --knob, --size and --stereo one way, and say what is wrong one way.
#include <gtest/gtest.h>

#include "frame/frame_arguments.h"

namespace fg {
namespace {

TEST(FrameArguments, knobs_are_name_equals_number_and_the_last_one_wins) {
    std::map<std::string, double> knobs;
    std::string error;
    ASSERT_TRUE(parse_knobs({"epsilon=0.5", "max_steps=64", "epsilon=2"}, knobs, error)) << error;
    EXPECT_EQ(knobs, (std::map<std::string, double>{{"epsilon", 2.0}, {"max_steps", 64.0}}));
}

TEST(FrameArguments, a_knob_without_a_name_or_a_whole_number_is_refused_in_one_form) {
    for (const char* bad : {"epsilon", "=1", "epsilon=", "epsilon=fast", "epsilon=1.5x", "epsilon=1,5"}) {
        std::map<std::string, double> knobs;
        std::string error;
        EXPECT_FALSE(parse_knobs({"overrelax=1.2", bad}, knobs, error)) << bad;
        EXPECT_EQ(error, std::string("--knob takes name=value, not '") + bad + "'");
    }
}

TEST(FrameArguments, sizes_are_w_x_h_within_the_limit) {
    std::uint32_t w = 0, h = 0;
    std::string error;
    ASSERT_TRUE(parse_size("640x360", 8192, w, h, error)) << error;
    EXPECT_EQ(w, 640u);
    EXPECT_EQ(h, 360u);
    for (const char* bad : {"12", "0x10", "10x0", "9000x10", "10x10x", "ax10", "-1x10", ""}) {
        EXPECT_FALSE(parse_size(bad, 8192, w, h, error)) << bad;
        EXPECT_NE(error.find("--size takes WxH"), std::string::npos) << error;
    }
    EXPECT_EQ(w, 640u) << "a refused size leaves the last good one";
}

TEST(FrameArguments, stereo_modes) {
    StereoMode mode = StereoMode::PerEye;
    std::string error;
    ASSERT_TRUE(parse_stereo("reproject", mode, error));
    EXPECT_EQ(mode, StereoMode::Reproject);
    EXPECT_FALSE(parse_stereo("mono", mode, error));
    EXPECT_EQ(error, "--stereo takes reproject, per-eye or naive, not 'mono'");
}

}  // namespace
}  // namespace fg
