#include "locomotion/viewer_step.h"

#include <algorithm>
#include <cmath>

#include "locomotion/comfort_vignette.h"
#include "locomotion/head_in_surface_fade.h"

namespace fg {

ViewerStep::ViewerStep(const vk::Context& ctx, const Pack& pack, const HeadPose& origin, bool wrap)
    : scene_(pack.manifest.scene),
      scene_gpu_(make_gpu_scene(scene_)),
      play_(origin, scene_.world_scale),
      scale_(scene_.world_scale),
      flight_(std::make_unique<ProbedFlight>(ctx, pack, scene_.locomotion, scene_.world_scale)),
      wrap_(wrap) {
    if (pack.manifest.period) period_ = glm::dvec3((*pack.manifest.period)[0], (*pack.manifest.period)[1], (*pack.manifest.period)[2]);
}

ViewerFrame ViewerStep::step(const ViewerControls& c) {
    const SnapTurnFrame turn = snap_.update(c.turn_stick, c.dt);
    if (turn.yaw_rad != 0.0) play_.turn_about(c.tracked_head, turn.yaw_rad);
    const double before = play_.world_scale();
    const double scale = scale_.update(c.scale_stick, c.dt, play_.point(c.tracked_head), c.ipd_m, locomotion().head_radius_m(),
                                       locomotion().guaranteed_clearance(play_.point(c.tracked_head)));
    if (scale != before) {
        play_.rescale_about(c.tracked_head, scale);
        flight_->set_world_scale(scale);
        scale_step_max_ = std::max(scale_step_max_, std::abs(scale / before - 1.0));
        if (*scale_.limited_by()) scale_limit_ = scale_.limited_by();
    }
    ViewerFrame f;
    f.head.orientation = play_.orientation(glm::normalize(c.tracked_orientation));
    f.head.position = play_.point(c.tracked_head);
    const glm::dvec3 direction = c.fly_direction ? play_.direction(*c.fly_direction)
                                                 : glm::mat3_cast(f.head.orientation) * glm::dvec3(0.0, 0.0, -1.0);
    // The tracked head's own motion in the scene (not flight, turns or scaling, which move the
    // play space): the look-ahead probe leads it.
    const glm::dvec3 tracked_velocity = c.dt > 0.0 && have_tracked_
                                            ? play_.direction(c.tracked_head - last_tracked_head_) * play_.world_scale() / c.dt
                                            : glm::dvec3(0.0);
    last_tracked_head_ = c.tracked_head;
    have_tracked_ = true;
    const glm::dvec3 moved = flight_->update(f.head.position, direction, c.throttle, c.dt, tracked_velocity);
    play_.move(moved - f.head.position);
    flown_ += moved - f.head.position;
    f.head.position = moved;
    // A looping scene: whole periods off the head before it is rendered, so its coordinates stay
    // inside one cell however far it flies. The probes' answers move with it.
    if (period_ && wrap_) {
        const glm::dvec3 shift = play_.wrap(c.tracked_head, *period_);
        if (shift != glm::dvec3(0.0)) {
            flight_->translate(-shift);
            f.head.position -= shift;
            ++wraps_;
        }
    }
    for (int i = 0; i < 3; ++i) head_extent_ = std::max(head_extent_, std::abs(f.head.position[i]));
    f.world_scale = play_.world_scale();
    // A head walked or leant into the surface (flight never takes it there) sees black.
    f.snap_brightness = turn.brightness;
    f.inside_brightness = head_in_surface_brightness(locomotion().answers(), f.head.position,
                                                     locomotion().head_radius_m() * play_.world_scale());
    f.brightness = std::min(f.snap_brightness, f.inside_brightness);
    // Artificial motion (flight, and mouse look) drives the comfort vignette, where the scene has one.
    f.scene = scene_gpu_;
    if (scene_gpu_.vignette > 0.0f)
        f.scene.vignette = static_cast<float>(comfort_vignette(glm::length(locomotion().velocity()) / play_.world_scale(), c.look_rate,
                                                               scene_gpu_.vignette));
    f.scene.fade = static_cast<float>(1.0 - f.brightness);
    return f;
}

}  // namespace fg
