#pragma once
// The tracking space placed in the scene. The headset tracks the head in metres in its LOCAL space;
// the play space puts that space somewhere in the scene: a position, a yaw on top of the scene
// camera's orientation, and a scale (scene units per metre). Flight moves it, snap turns turn it
// about the head, world-scale changes scale it about the head, and looping scenes wrap it by whole
// periods, so the head never jumps in the image.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "frame/stereo_rig.h"

namespace fg {

class PlaySpace {
public:
    PlaySpace(const HeadPose& origin, double world_scale);

    glm::dvec3 point(const glm::dvec3& tracked) const;          // metres in LOCAL -> scene
    glm::dvec3 direction(const glm::dvec3& tracked) const;      // rotation only
    glm::dquat orientation(const glm::dquat& tracked) const;
    double world_scale() const { return scale_; }

    void move(const glm::dvec3& scene_delta) { position_ += scene_delta; }
    // Turns by `yaw_rad` about the tracking space's up through the tracked head: the head keeps its
    // scene position and turns.
    void turn_about(const glm::dvec3& tracked_head, double yaw_rad);
    // A new scale about the tracked head: the head keeps its scene position.
    void rescale_about(const glm::dvec3& tracked_head, double world_scale);
    // Shifts by whole periods (a component <= 0 is not periodic) so that the head lies in the
    // central cell [-period/2, period/2); returns the shift (scene units, zero when none).
    glm::dvec3 wrap(const glm::dvec3& tracked_head, const glm::dvec3& period);

private:
    glm::dvec3 position_;
    glm::dquat orientation_;
    double scale_;
};

// The cell shift that brings `p` into [-period/2, period/2) on each periodic axis, the same cell
// choice as the xform.repeat node (floor(p / period + 0.5)).
glm::dvec3 periodic_cell_shift(const glm::dvec3& p, const glm::dvec3& period);

}  // namespace fg
