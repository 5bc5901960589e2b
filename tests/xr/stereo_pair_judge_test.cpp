// The test runtime's judgement of the frames it receives must be able to fail.
#include <gtest/gtest.h>

#include "frame_inspector.h"

namespace fgxrt {
namespace {

EyeImage flat(std::uint8_t value) {
    EyeImage e;
    e.width = e.height = 16;
    e.format = VK_FORMAT_R8G8B8A8_UNORM;
    e.rgba.assign(16 * 16 * 4, value);
    return e;
}

EyeImage gradient(int shift) {
    EyeImage e = flat(0);
    for (std::size_t i = 0; i < 256; ++i)
        for (int c = 0; c < 3; ++c) e.rgba[4 * i + c] = static_cast<std::uint8_t>((i * 3 + static_cast<std::size_t>(shift)) % 256);
    return e;
}

TEST(StereoPairJudge, BlankEyesAreRejected) {
    auto v = judge_stereo_pair(flat(40), gradient(0));
    ASSERT_FALSE(v.problems.empty());
    EXPECT_NE(v.problems[0].find("left eye is blank"), std::string::npos);
}

TEST(StereoPairJudge, IdenticalEyesAreRejected) {
    auto v = judge_stereo_pair(gradient(0), gradient(0));
    ASSERT_EQ(v.problems.size(), 1u);
    EXPECT_NE(v.problems[0].find("same image"), std::string::npos);
}

TEST(StereoPairJudge, TwoDifferentDetailedEyesPass) {
    auto v = judge_stereo_pair(gradient(0), gradient(7));
    EXPECT_TRUE(v.problems.empty());
    EXPECT_GT(v.eyes_differ_fraction, 0.5);
}

TEST(StereoPairJudge, AMissingReadbackIsAProblem) {
    EyeImage none;
    auto v = judge_stereo_pair(none, gradient(0));
    EXPECT_FALSE(v.problems.empty());
}

}  // namespace
}  // namespace fgxrt
