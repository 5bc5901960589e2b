#pragma once
// Lays out the specialization constants of a pack: the global knobs (common/spec_constants.h)
// and one per node knob input bound to a literal (bias.<node>, iterations.<node>), in node order.
#include <vector>

#include "ir/ir_graph.h"
#include "pack/manifest.h"

namespace fg {

struct SpecializationLayout {
    std::vector<ManifestSpecConstant> constants;
    std::vector<ManifestFractal> fractals;
};

// Assigns knob ids into the IR (IrInput::knob_id) and returns the table.
SpecializationLayout assign_specialization(IrGraph& ir, double step_scale);

}  // namespace fg
