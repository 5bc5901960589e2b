// Camera paths: keys are met exactly at their times, eased in between, scale zooms geometrically,
// bad files get errors naming the JSON pointer; frame ranges and shards cover a path exactly.
#include <gtest/gtest.h>

#include "offline/camera_path.h"
#include "offline/frame_range.h"

using namespace fg;

namespace {

std::optional<CameraPath> parse(const std::string& text, Diagnostics& diag) {
    return CameraPath::parse(nlohmann::json::parse(text), 1.0, diag);
}

const char* kThreeKeys = R"({
  "format": "fractograph-camera-path", "version": 1, "fps": 10,
  "keyframes": [
    {"time": 1.0, "position": [0, 0, 3], "target": [0, 0, 0]},
    {"time": 2.0, "position": [3, 0, 0], "target": [0, 0, 0], "world_scale": 4.0, "ease": "in-out"},
    {"time": 3.0, "position": [0, 3, 0], "orientation": [0.7071068, -0.7071068, 0, 0], "world_scale": 16.0}
  ]
})";

double angle_between(const glm::dquat& a, const glm::dquat& b) {
    return 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(a, b))));
}

}  // namespace

TEST(CameraPath, passes_through_every_key_at_its_time) {
    Diagnostics diag;
    auto path = parse(kThreeKeys, diag);
    ASSERT_TRUE(path) << diag.format();
    // 1 s to 3 s at 10 fps, both ends included.
    EXPECT_EQ(path->frame_count(), 21);
    for (const auto& key : path->keys()) {
        CameraSample s = path->at(key.time);
        EXPECT_LT(glm::length(s.head.position - key.position), 1e-9);
        EXPECT_LT(angle_between(s.head.orientation, key.orientation), 1e-6);
        EXPECT_NEAR(s.world_scale, key.world_scale, 1e-9);
    }
    EXPECT_LT(glm::length(path->sample(10).head.position - glm::dvec3(3, 0, 0)), 1e-9);
    // A target key looks at its target: -z of the head points at the origin.
    CameraSample first = path->sample(0);
    glm::dvec3 forward = -glm::mat3_cast(first.head.orientation)[2];
    EXPECT_LT(glm::length(forward - glm::dvec3(0, 0, -1)), 1e-9);
}

TEST(CameraPath, a_last_key_written_with_seven_decimals_keeps_its_frame) {
    Diagnostics diag;
    auto path = parse(R"({"format": "fractograph-camera-path", "version": 1, "fps": 30, "keyframes": [
        {"time": 0.0, "position": [0, 0, 3], "target": [0, 0, 0]},
        {"time": 3.3333333, "position": [3, 0, 0], "target": [0, 0, 0]}]})",
                      diag);
    ASSERT_TRUE(path) << diag.format();
    EXPECT_EQ(path->frame_count(), 101);  // frames 0 to 100: 100 / 30 s is the last key's time
    CameraSample last = path->sample(100);
    EXPECT_LT(glm::length(last.head.position - glm::dvec3(3, 0, 0)), 1e-6);
}

TEST(CameraPath, zooms_by_the_same_factor_each_second_and_eases_where_asked) {
    Diagnostics diag;
    auto path = parse(kThreeKeys, diag);
    ASSERT_TRUE(path) << diag.format();
    // Linear timing from 1 to 4: half-way is the geometric mean 2, not 2.5.
    EXPECT_NEAR(path->at(1.5).world_scale, 2.0, 1e-9);
    // In-out easing from 4 to 16: a quarter of the way in time is 15.6 % of the way (smoothstep).
    double s = 0.25 * 0.25 * (3.0 - 2.0 * 0.25);
    EXPECT_NEAR(path->at(2.25).world_scale, 4.0 * std::pow(4.0, s), 1e-9);
    // Between two target keys the camera keeps looking at the (moving) target: here the origin.
    CameraSample mid = path->at(1.5);
    glm::dvec3 forward = -glm::mat3_cast(mid.head.orientation)[2];
    EXPECT_LT(glm::length(forward - glm::normalize(-mid.head.position)), 1e-9);
}

TEST(CameraPath, a_bad_file_gets_errors_naming_the_keyframe_field) {
    Diagnostics diag;
    auto path = parse(R"({"format": "fractograph-camera-path", "version": 1, "keyframes": [
        {"time": 0, "position": [0, 0], "target": [0, 0, 0]},
        {"time": 0, "position": [1, 0, 0], "target": [0, 0, 0], "orientation": [1, 0, 0, 0]},
        {"time": 1, "position": [1, 0, 0], "target": [0, 0, 0], "ease": "bouncy", "zoom": 2}]})",
                      diag);
    EXPECT_FALSE(path);
    std::string text = diag.format();
    EXPECT_NE(text.find("/keyframes/0/position"), std::string::npos) << text;
    EXPECT_NE(text.find("/keyframes/1/time"), std::string::npos) << text;
    EXPECT_NE(text.find("either a target"), std::string::npos) << text;
    EXPECT_NE(text.find("/keyframes/2/ease"), std::string::npos) << text;
    EXPECT_NE(text.find("/keyframes/2/zoom"), std::string::npos) << text;
}

TEST(FrameRange, shards_cover_the_range_exactly_once) {
    std::string error;
    auto range = parse_frame_range("5:105", 200, error);
    ASSERT_TRUE(range) << error;
    for (int n : {1, 3, 7, 100, 150}) {
        int next = range->begin;
        for (int i = 0; i < n; ++i) {
            FrameRange s = shard_of(*range, i, n);
            EXPECT_EQ(s.begin, next);
            EXPECT_LE(s.size(), (range->size() + n - 1) / n);
            next = s.end;
        }
        EXPECT_EQ(next, range->end);
    }
    EXPECT_EQ(parse_frame_range(":", 200, error)->size(), 200);
    EXPECT_EQ(parse_frame_range("7", 200, error)->size(), 1);
    EXPECT_FALSE(parse_frame_range("10:5", 200, error));
    EXPECT_FALSE(parse_frame_range("0:201", 200, error));
    EXPECT_FALSE(parse_frame_range("a:b", 200, error));
    int i = 0, n = 0;
    EXPECT_TRUE(parse_shard("3/8", i, n, error));
    EXPECT_EQ(i, 3);
    EXPECT_FALSE(parse_shard("8/8", i, n, error));
}
