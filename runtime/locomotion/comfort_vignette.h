#pragma once
// The comfort vignette: darkening the edges of the view while the viewer is moved artificially
// cuts vection, the cause of most flight sickness. Its strength follows the flight's linear speed
// (in metres per second: scene units over the world scale) and the view's angular speed, up to
// the scene's vignette strength; at rest there is none. Packs without a vignette block have no
// vignette effect compiled in, so nothing darkens there.
namespace fg {

struct ComfortVignetteSettings {
    double full_at_speed = 2.0;            // m/s at which the vignette is at full strength
    double full_at_turn = 1.5;             // rad/s likewise
};

// Strength in [0, max_strength].
double comfort_vignette(double speed_m_per_s, double turn_rad_per_s, double max_strength,
                        const ComfortVignetteSettings& settings = {});

}  // namespace fg
