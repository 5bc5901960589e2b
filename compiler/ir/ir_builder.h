#pragma once
// Graph -> typed IR: orders nodes, drops what no output reaches, resolves every input, infers
// generic types and checks types and contexts.
#include <optional>

#include "common/diagnostics.h"
#include "graph/graph.h"
#include "graph/node_library.h"
#include "ir_graph.h"

namespace fg {

std::optional<IrGraph> build_ir(const Graph& graph, const NodeLibrary& library, Diagnostics& diag);

}  // namespace fg
