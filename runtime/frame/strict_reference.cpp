#include "strict_reference.h"

namespace fg {

FrameSettings strict_reference_settings(const PackManifest& pack, std::uint32_t width, std::uint32_t height) {
    FrameSettings f;
    f.width = width;
    f.height = height;
    f.stereo = StereoMode::Naive;
    f.foveation = 0.0;
    const auto* step = pack.find_spec("step_scale");
    f.knobs = {{"epsilon", 0.05}, {"max_steps", 4000}, {"step_scale", 0.5 * (step ? step->value : 1.0)}};
    return f;
}

}  // namespace fg
