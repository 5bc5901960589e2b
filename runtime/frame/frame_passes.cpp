#include "frame_passes.h"

namespace fg {

// One builder per pass kind, each in its own file beside its shader template (shaders/<name>.comp).
void add_naive_passes(FrameGraph& g);
void add_conemarch_passes(FrameGraph& g);
void add_reproject_passes(FrameGraph& g);
void add_shade_passes(FrameGraph& g);
void add_fovea_passes(FrameGraph& g);
void add_aov_passes(FrameGraph& g);
void add_taa_passes(FrameGraph& g);

const std::vector<PassKind>& frame_pass_kinds() {
    static const std::vector<PassKind> kinds{
        {"naive", add_naive_passes},         {"conemarch", add_conemarch_passes}, {"reproject", add_reproject_passes},
        {"shade", add_shade_passes},         {"fovea", add_fovea_passes},         {"taa", add_taa_passes},
        {"aov", add_aov_passes},
    };
    return kinds;
}

}  // namespace fg
