#pragma once
// The resolve pass after a marching pass with persistent lanes (shader: shaders/resolve.comp).
#include <string>

#include "frame_graph.h"

namespace fg {

// The rays buffer a view's marching pass binds with persistent lanes, room for every pixel (none
// without: the passes leave the binding unused). Returns its name.
std::string add_rays_buffer(FrameGraph& g, int view, std::uint32_t width, std::uint32_t height);
// Moves the rays buffer of `view` into its depth, glow and, if `levels` names one, level-0 atlas.
void add_resolve_pass(FrameGraph& g, int view, std::uint32_t width, std::uint32_t height, const std::string& levels);

}  // namespace fg
