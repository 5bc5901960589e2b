#pragma once
// Propagates a static bound of each value's Lipschitz constant with respect to the sample point,
// node by node with each definition's rule, to the distance output. The march scales every step
// by 1 / L, so a graph that stretches space (a scale below 1, a twist, a displacement) never
// oversteps, and one that shrinks it is not marched more timidly than it needs.
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "ir/ir_graph.h"

namespace fg {

struct LipschitzResult {
    double bound = 1.0;                 // for the distance output (after any fallback)
    bool exact = true;                  // false when a rule was unknown and the fallback was used
    std::vector<std::string> notes;     // why, for the manifest and `fgc check`
    std::vector<double> node_bounds;    // per IR node, its first output (for tools and tests)
};

LipschitzResult analyse_lipschitz(const IrGraph& ir, Diagnostics& diag);

}  // namespace fg
