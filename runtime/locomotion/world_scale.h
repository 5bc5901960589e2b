#pragma once
// Changing the world scale (scene units per metre: how big the viewer is in the fractal) while
// flying. The stick moves a target; the scale follows it exponentially, in log space, so it never
// jumps and a doubling takes as long at any size. The eye separation and the head's tracked motion
// both scale with it (the play space and the stereo rig read the one value), and so do the flight
// speed and the head radius. Bounds come from the scene:
//  - a floor: the eye separation in scene units stays at least `float_spacings` times the spacing
//    of floats at the head's coordinates, so the two eyes never collapse onto one float position;
//  - a ceiling from the probes: the head radius (metres times the scale) never outgrows the empty
//    ball the collision probes guarantee around the head, so growing never puts an eye inside;
//  - and the scene's own range, relative to its starting scale.
#include <glm/glm.hpp>

namespace fg {

struct WorldScaleSettings {
    double time_constant_s = 0.15;   // the scale covers 63 % of the way to its target in this time
    double rate_per_s = 1.0;         // full stick: the target changes by e (2.7x) per second
    double dead_zone = 0.15;         // |stick| under this leaves the target alone
    double min_factor = 1e-4, max_factor = 1e4;   // of the scene's starting scale
    double float_spacings = 1024.0;
};

// Smallest world scale whose eye separation (`ipd_m` metres) spans `spacings` float steps at `head`.
double float_floor_scale(const glm::dvec3& head, double ipd_m, double spacings);

class WorldScale {
public:
    explicit WorldScale(double initial, const WorldScaleSettings& settings = {});

    // `stick` in [-1, 1]: up grows the viewer (the world looks smaller), down shrinks the viewer.
    // `clearance`: the empty distance the probes guarantee at the head (scene units; 0 = none
    // known, so the scale does not grow). Returns the new scale.
    double update(double stick, double dt, const glm::dvec3& head, double ipd_m, double head_radius_m, double clearance);

    double current() const { return current_; }
    double target() const { return target_; }
    // What bounded the last update, for the log: "", "float floor", "clearance", "scene range".
    const char* limited_by() const { return limited_by_; }

private:
    WorldScaleSettings settings_;
    double initial_, current_, target_;
    const char* limited_by_ = "";
};

}  // namespace fg
