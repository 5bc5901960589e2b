#pragma once
// Writes a graph document back as text in the gallery's layout (one top-level key per line, one
// node, param or output per line), so a tool that edits a graph (fgc calibrate) leaves a diff a
// person can read.
#include <string>

#include <nlohmann/json.hpp>

namespace fg {

std::string format_graph_text(const nlohmann::ordered_json& graph);

}  // namespace fg
