#include "head_trace.h"

#include <cmath>
#include <functional>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "locomotion/locomotion.h"
#include "locomotion/snap_turn.h"

namespace fg::bench {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kFrameS = 1.0 / kHeadsetHz;

glm::dvec3 forward_of(const HeadPose& head) { return -(glm::mat3_cast(head.orientation)[2]); }

// `start` turned by `yaw` about the scene's up (positive: left), then pitched by `pitch` about the
// head's own right axis (positive: up), as a neck does.
glm::dquat turned(const HeadPose& start, const glm::dvec3& up, double yaw, double pitch) {
    return glm::normalize(glm::angleAxis(yaw, up) * start.orientation *
                          glm::angleAxis(pitch, glm::dvec3(1.0, 0.0, 0.0)));
}

HeadTrace trace(std::string name, std::string motion, double world_scale, int frames,
                const std::function<TraceFrame(int, double)>& frame_at) {
    HeadTrace t{std::move(name), std::move(motion), world_scale, {}};
    for (int i = 0; i < frames; ++i) {
        TraceFrame f = frame_at(i, i * kFrameS);
        f.time = i * kFrameS;
        t.frames.push_back(f);
    }
    return t;
}

// The gaze circles 15 degrees around and below the start at a constant 60 degrees a second.
HeadTrace look_around(const HeadPose& start, const glm::dvec3& up, double world_scale, int frames) {
    const double radius = 15.0 * kDegree, omega = 60.0 * kDegree / radius;
    return trace("look_around", "gaze circling (15° radius, through the start), the head at 60°/s", world_scale, frames,
                 [&](int, double t) {
                     return TraceFrame{{start.position, turned(start, up, radius * std::sin(omega * t),
                                                               -radius * (1.0 - std::cos(omega * t)))}};
                 });
}

// The head turns 60 degrees to the left, back through the start and on to the right, passing the
// start at 300 degrees a second.
HeadTrace fast_turn(const HeadPose& start, const glm::dvec3& up, double world_scale, int frames) {
    const double amplitude = 60.0 * kDegree, omega = 300.0 * kDegree / amplitude;
    return trace("fast_turn", "yaw ±60° at up to 300°/s", world_scale, frames, [&](int, double t) {
        return TraceFrame{{start.position, turned(start, up, amplitude * std::sin(omega * t), 0.0)}};
    });
}

// Walking to the right past the surface the start looks at, level, still looking at it, the head
// bobbing 2 cm at two steps a second. The walker stops where the next step would bring the head
// closer to the surface than the head's radius.
HeadTrace walk(const CpuEvaluator& twin, const SceneSettings& s, const HeadPose& start, int frames) {
    const glm::dvec3 up = glm::normalize(s.camera.up);
    glm::dvec3 right = glm::mat3_cast(start.orientation)[0];
    right = glm::normalize(right - up * glm::dot(right, up));
    const double speed = 1.4 * s.world_scale, bob = 0.02 * s.world_scale, steps_hz = 2.0;
    const double clearance = s.locomotion.head_radius * s.world_scale;
    glm::dvec3 path = start.position;   // where the head would be without the bob
    const char* motion = "walking right past the surface at 1.4 m/s, looking at it, 2 cm head bob";
    return trace("walk", motion, s.world_scale, frames, [&](int i, double t) {
        glm::dvec3 lift = up * (bob * std::sin(2.0 * std::numbers::pi * steps_hz * t));
        glm::dvec3 next = path + right * (speed * kFrameS);
        if (i > 0 && twin.distance(next + lift) > clearance) path = next;
        return TraceFrame{{path + lift, start.orientation}};
    });
}

// Controller flight along the start's gaze at full throttle, the gallery's speed rule and
// collision bound (locomotion.h), the probes answered at once by the CPU twin.
HeadTrace flight(const CpuEvaluator& twin, const SceneSettings& s, const HeadPose& start, int frames) {
    Locomotion locomotion(s.locomotion, s.world_scale);
    const glm::dvec3 direction = forward_of(start);
    glm::dvec3 head = start.position;
    return trace("flight", "controller flight towards the surface at the gallery's speed", s.world_scale, frames,
                 [&](int i, double) {
                     if (i > 0) {
                         ProbeResult answer;
                         for (const auto& p : locomotion.probe_points(head, locomotion.velocity()))
                             answer.samples.push_back({p, twin.distance(p), {}});
                         locomotion.on_probe(answer);
                         head = locomotion.step(head, direction, 1.0, kFrameS);
                     }
                     return TraceFrame{{head, start.orientation}};
                 });
}

// The head holds still while the stick snaps the view 90 degrees right and, when the trace is long
// enough, back left: the fade of snap_turn.h, the yaw in the one black frame.
HeadTrace snap_turn(const HeadPose& start, const glm::dvec3& up, double world_scale, int frames) {
    SnapTurn snap;
    HeadPose head = start;
    const int right_at = std::max(1, frames / 10), left_at = frames / 2;
    return trace("snap_turn", "90° snap turns with the fade, right and back", world_scale, frames, [&](int i, double) {
        double stick = i == right_at ? 1.0 : (i == left_at ? -1.0 : 0.0);
        SnapTurnFrame turn = snap.update(stick, kFrameS);
        head.orientation = glm::normalize(glm::angleAxis(turn.yaw_rad, up) * head.orientation);
        return TraceFrame{head, 0.0, turn.brightness};
    });
}

}  // namespace

const std::vector<std::string>& head_trace_names() {
    static const std::vector<std::string> names = {"look_around", "walk", "fast_turn", "flight", "snap_turn"};
    return names;
}

std::vector<HeadTrace> make_head_traces(const CpuEvaluator& twin, const SceneSettings& scene, const HeadPose& start,
                                        int frames) {
    const glm::dvec3 up = glm::normalize(scene.camera.up);
    return {look_around(start, up, scene.world_scale, frames), walk(twin, scene, start, frames),
            fast_turn(start, up, scene.world_scale, frames), flight(twin, scene, start, frames),
            snap_turn(start, up, scene.world_scale, frames)};
}

}  // namespace fg::bench
