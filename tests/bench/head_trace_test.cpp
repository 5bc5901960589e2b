// The head traces of `fgplay bench --sequence` move as their names promise, at 90 Hz, and never
// take the head into the surface: checked on the gallery scenes with their CPU twins.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>

#include "bench_views.h"
#include "compiler.h"
#include "head_trace.h"

namespace fg::bench {
namespace {

constexpr int kFrames = 90;
constexpr double kDegree = std::numbers::pi / 180.0;

struct Flown {
    std::unique_ptr<IrGraph> ir;
    std::optional<CpuEvaluator> twin;
    HeadPose start;
    LocomotionSettings locomotion;
    std::vector<HeadTrace> traces;

    const HeadTrace& trace(const std::string& name) const {
        for (const auto& t : traces)
            if (t.name == name) return t;
        throw std::runtime_error("no trace " + name);
    }
    double clearance() const { return locomotion.head_radius * ir->scene.world_scale; }
};

Flown fly(const std::string& gallery_name) {
    std::ifstream in(std::string(FG_SOURCE_DIR) + "/graphs/gallery/" + gallery_name + ".json");
    std::stringstream text;
    text << in.rdbuf();
    Diagnostics diag;
    auto ir = load_and_lower(text.str(), NodeLibrary::builtin(), diag);
    if (!ir) throw std::runtime_error(diag.format());
    Flown f;
    f.ir = std::make_unique<IrGraph>(std::move(*ir));
    f.twin = CpuEvaluator::create(*f.ir, diag);
    if (!f.twin) throw std::runtime_error(diag.format());
    for (const auto& v : make_bench_views(*f.twin, f.ir->scene))
        if (v.name == "filled") f.start = v.head;
    f.locomotion = f.ir->scene.locomotion;
    f.traces = make_head_traces(*f.twin, f.ir->scene, f.start, kFrames);
    return f;
}

glm::dvec3 gaze(const HeadPose& h) { return -(glm::mat3_cast(h.orientation)[2]); }

// Degrees per second the head turns between consecutive frames.
std::vector<double> turn_speeds(const HeadTrace& t) {
    std::vector<double> out;
    for (std::size_t i = 1; i < t.frames.size(); ++i) {
        glm::dquat step = glm::inverse(t.frames[i - 1].head.orientation) * t.frames[i].head.orientation;
        out.push_back(2.0 * std::acos(std::min(1.0, std::abs(step.w))) / kDegree * kHeadsetHz);
    }
    return out;
}

class HeadTraces : public ::testing::TestWithParam<std::string> {};

TEST_P(HeadTraces, every_trace_has_its_frames_at_90_hz_and_starts_where_the_headset_is_filled) {
    Flown f = fly(GetParam());
    ASSERT_EQ(f.traces.size(), head_trace_names().size());
    for (const auto& t : f.traces) {
        ASSERT_EQ(t.frames.size(), static_cast<std::size_t>(kFrames)) << t.name;
        EXPECT_NEAR(t.frames[1].time - t.frames[0].time, 1.0 / 90.0, 1e-12) << t.name;
        EXPECT_LT(glm::length(t.frames[0].head.position - f.start.position), 1e-9) << t.name;
        for (const auto& fr : t.frames)
            EXPECT_GT(f.twin->distance(fr.head.position), f.clearance())
                << t.name << " takes the head into the surface";
    }
}

TEST_P(HeadTraces, looking_around_turns_the_head_at_sixty_degrees_a_second) {
    Flown f = fly(GetParam());
    for (double speed : turn_speeds(f.trace("look_around"))) EXPECT_NEAR(speed, 60.0, 0.5);
}

TEST_P(HeadTraces, the_fast_turn_peaks_at_three_hundred_degrees_a_second) {
    Flown f = fly(GetParam());
    auto speeds = turn_speeds(f.trace("fast_turn"));
    EXPECT_NEAR(*std::max_element(speeds.begin(), speeds.end()), 300.0, 1.0);
}

TEST_P(HeadTraces, the_walker_walks_at_one_point_four_metres_a_second_with_a_two_centimetre_head_bob) {
    Flown f = fly(GetParam());
    const HeadTrace& walk = f.trace("walk");
    const double ws = f.ir->scene.world_scale;
    // Two steps a second: the bob is back where it began every 45 frames.
    const glm::dvec3 a = walk.frames[0].head.position, b = walk.frames[45].head.position;
    EXPECT_NEAR(glm::length(b - a) / ws, 1.4 * 0.5, 1e-6) << "the walker stopped or strayed";
    const glm::dvec3 line = glm::normalize(b - a);
    double bob = 0.0;
    for (int i = 0; i <= 45; ++i) {
        glm::dvec3 p = walk.frames[static_cast<std::size_t>(i)].head.position - a;
        bob = std::max(bob, glm::length(p - line * glm::dot(p, line)) / ws);
    }
    EXPECT_GT(bob, 0.015);
    EXPECT_LE(bob, 0.02 + 1e-9);
}

TEST_P(HeadTraces, the_flight_keeps_the_gallery_speed_rule_proportional_to_the_distance) {
    Flown f = fly(GetParam());
    const HeadTrace& flight = f.trace("flight");
    const double ws = f.ir->scene.world_scale;
    double flown = 0.0;
    for (std::size_t i = 1; i < flight.frames.size(); ++i) {
        glm::dvec3 before = flight.frames[i - 1].head.position;
        double speed = glm::length(flight.frames[i].head.position - before) * kHeadsetHz;
        double rule = std::min(f.locomotion.speed_per_distance * f.twin->distance(before), f.locomotion.max_speed * ws);
        EXPECT_LE(speed, rule * 1.0001) << "frame " << i;
        flown += speed / kHeadsetHz;
    }
    EXPECT_GT(flown, 0.1 * f.twin->distance(f.start.position)) << "the flight went nowhere";
}

TEST_P(HeadTraces, a_snap_turn_turns_ninety_degrees_in_its_one_black_frame) {
    Flown f = fly(GetParam());
    const HeadTrace& snap = f.trace("snap_turn");
    const glm::dvec3 up = glm::normalize(f.ir->scene.camera.up);
    int black = 0;
    for (std::size_t i = 1; i < snap.frames.size(); ++i) {
        // The turn is about the vertical: compare the gazes' horizontal directions.
        auto level = [&](const HeadPose& h) {
            glm::dvec3 g = gaze(h);
            return glm::normalize(g - up * glm::dot(g, up));
        };
        double turned =
            std::acos(std::clamp(glm::dot(level(snap.frames[i - 1].head), level(snap.frames[i].head)), -1.0, 1.0));
        if (snap.frames[i].brightness <= 0.0) {
            ++black;
            EXPECT_NEAR(turned / kDegree, 90.0, 1.0) << "frame " << i;
        } else {
            EXPECT_LT(turned, 1e-9) << "the head holds still outside the black frame, frame " << i;
        }
    }
    EXPECT_EQ(black, 2) << "right and back within 90 frames";
    EXPECT_LT(snap.frames[15].brightness, 1.0) << "the fade is on its way";
}

INSTANTIATE_TEST_SUITE_P(Gallery, HeadTraces, ::testing::Values("mandelbulb", "mandelbox", "kleinian"));

}  // namespace
}  // namespace fg::bench
