#pragma once
// Folds every node whose inputs are all constants into its value (computed by the node's CPU
// twin in double precision) and removes nodes no output reaches any more.
#include "common/diagnostics.h"
#include "ir_graph.h"

namespace fg {

struct FoldingStats {
    int folded = 0;
    int removed = 0;
};

FoldingStats fold_constants(IrGraph& ir, Diagnostics& diag);
// Drop nodes no graph output reaches; returns how many went.
int remove_dead_nodes(IrGraph& ir);

}  // namespace fg
