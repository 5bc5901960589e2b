#pragma once
// Loads a graph from JSON text: parse, check the format and version (upgrading old versions step by
// step), read params, nodes, bindings, outputs and scene settings, and check references and cycles.
// Every problem becomes a diagnostic with the JSON pointer and node id; nothing throws.
#include <optional>
#include <string_view>

#include "common/diagnostics.h"
#include "graph.h"
#include "node_library.h"

namespace fg {

std::optional<Graph> load_graph(std::string_view json_text, const NodeLibrary& library, Diagnostics& diag);
std::optional<Graph> load_graph_file(const std::string& path, const NodeLibrary& library, Diagnostics& diag);

}  // namespace fg
