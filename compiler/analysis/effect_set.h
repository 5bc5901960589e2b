#pragma once
// Which effects a scene uses: from the nodes that survive dead-node removal, the outputs the graph
// binds, the runtime values its nodes read (the normal) and its scene settings. Code for anything
// else is never emitted, and the runtime allocates nothing for it.
#include "common/effects.h"
#include "ir/ir_graph.h"

namespace fg {

EffectSet find_effects(const IrGraph& ir);

}  // namespace fg
