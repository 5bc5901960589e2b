#include "depth_of_field.h"

#include <stdexcept>

namespace fg {

std::optional<double> distance_at_view_centre(HeadlessRenderer& renderer, const HeadPose& head, double time,
                                              std::uint32_t frame_index) {
    // A plain frame looks from the lens's centre; only render_samples moves the eyes over the lens.
    renderer.set_lens(glm::dvec2(0.0));
    RenderedFrame f = renderer.render(head, time, frame_index);
    const auto& g = renderer.graph();
    const float t = f.depth_left.at(static_cast<std::size_t>(g.height / 2) * g.width + g.width / 2);
    if (t < 0.0f) return std::nullopt;
    return t;
}

double focus_depth_of_field(HeadlessRenderer& renderer, double aperture, double focus, const HeadPose& head, double time,
                            std::uint32_t frame_index) {
    if (aperture > 0.0 && focus <= 0.0) {
        auto centre = distance_at_view_centre(renderer, head, time, frame_index);
        if (!centre)
            throw std::runtime_error("depth of field: the view's centre sees nothing to focus on; give --focus DISTANCE");
        focus = *centre;
    }
    renderer.set_depth_of_field(aperture, focus);
    return focus;
}

}  // namespace fg
