#pragma once
// Every kind of pass, in frame order. Each builder adds its passes, and the images they write, to
// the graph for the views and settings that need them, or nothing: "simulate only what the scene
// calls for" is decided there. A new pass is one builder file and one line in frame_passes.cpp.
#include <vector>

namespace fg {

class FrameGraph;

struct PassKind {
    const char* name;
    void (*add)(FrameGraph& graph);
};

const std::vector<PassKind>& frame_pass_kinds();

}  // namespace fg
