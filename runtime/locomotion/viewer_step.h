#pragma once
// One frame of a viewer, the same for the headset (fgplay xr) and the desktop window (fgplay
// view): from the tracked head and the controls to the head in the scene, how bright the frame is,
// and the scene uniforms it is drawn with. Snap turns with their fade, smooth world scale, probed
// flight, wrapping a looping scene, the head-in-surface fade and the comfort vignette all happen
// here; each loop keeps only what is its own: where the input comes from and where images go.
//
// The tracked head lives in a tracking space in metres that the play space places in the scene
// (play_space.h). The headset's is its LOCAL space, placed at the scene camera. The desktop's head
// stays at the origin of a space placed at the camera's position without turning it, and the mouse
// turns the head: so both fly, turn and scale the same way.
#include <memory>
#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "frame/gpu_uniforms.h"
#include "locomotion/play_space.h"
#include "locomotion/probed_flight.h"
#include "locomotion/snap_turn.h"
#include "locomotion/world_scale.h"
#include "pack/pack_reader.h"

namespace fg {

struct ViewerControls {
    double dt = 0.0;                                   // seconds since the last frame
    glm::dvec3 tracked_head{0.0};                      // metres, in the tracking space
    glm::dquat tracked_orientation{1.0, 0.0, 0.0, 0.0};
    double ipd_m = 0.064;
    double turn_stick = 0.0;                           // snap_turn.h: past +-0.7 turns
    double scale_stick = 0.0;                          // > 0 grows the viewer, < 0 shrinks it
    std::optional<glm::dvec3> fly_direction;           // unit, in the tracking space; none: the gaze
    double throttle = 0.0;                             // times the distance-proportional speed
    double look_rate = 0.0;                            // rad/s of turning that is not the head's own (mouse look)
};

struct ViewerFrame {
    HeadPose head;                  // in the scene
    double world_scale = 1.0;
    double brightness = 1.0;        // 0 is black: nothing to render
    double snap_brightness = 1.0;   // the snap turn's share of it
    double inside_brightness = 1.0; // the head-in-surface fade's share (< 1: the head is at or in the surface)
    GpuScene scene;                 // the pack's uniforms with this frame's fade and vignette
};

class ViewerStep {
public:
    // `origin`: where the tracking space's origin sits in the scene, and how it is turned.
    ViewerStep(const vk::Context& ctx, const Pack& pack, const HeadPose& origin, bool wrap);

    ViewerFrame step(const ViewerControls& c);

    const Locomotion& locomotion() const { return flight_->locomotion(); }
    const PlaySpace& play_space() const { return play_; }
    const SnapTurn& snap() const { return snap_; }
    const std::optional<glm::dvec3>& period() const { return period_; }
    int wraps() const { return wraps_; }
    double largest_scale_change() const { return scale_step_max_; }   // relative, per frame
    const char* scale_limit() const { return scale_limit_; }          // what last held the scale, or ""
    const glm::dvec3& flown() const { return flown_; }                // scene units the flight moved the head
    double head_extent() const { return head_extent_; }               // the head's largest coordinate so far

private:
    SceneSettings scene_;
    GpuScene scene_gpu_;
    PlaySpace play_;
    WorldScale scale_;
    SnapTurn snap_;
    std::unique_ptr<ProbedFlight> flight_;
    std::optional<glm::dvec3> period_;
    bool wrap_;
    glm::dvec3 last_tracked_head_{0.0};
    bool have_tracked_ = false;
    int wraps_ = 0;
    double scale_step_max_ = 0.0;
    const char* scale_limit_ = "";
    glm::dvec3 flown_{0.0};
    double head_extent_ = 0.0;
};

}  // namespace fg
