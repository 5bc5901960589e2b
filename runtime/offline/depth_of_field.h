#pragma once
// Depth of field for offline frames: a thin lens whose samples jittered_samples.h averages. Where
// the user gives no focus distance, the lens focuses on what the view's centre sees.
#include <optional>

#include "frame/headless_renderer.h"

namespace fg {

// The hit distance (scene units) at the centre pixel of the first eye's view from `head`, or
// nothing where that ray misses. Renders one plain frame.
std::optional<double> distance_at_view_centre(HeadlessRenderer& renderer, const HeadPose& head, double time,
                                              std::uint32_t frame_index);

// Sets `renderer`'s thin lens: `aperture` (diameter, scene units) focused at `focus`, or at the
// view's centre where focus is 0. Throws std::runtime_error when the centre sees nothing to focus on.
// Returns the focus distance used.
double focus_depth_of_field(HeadlessRenderer& renderer, double aperture, double focus, const HeadPose& head, double time,
                            std::uint32_t frame_index);

}  // namespace fg
