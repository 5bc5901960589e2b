#pragma once
// A graph as the page sends it back, written in the canonical layout (graph/graph_text_writer.h).
// JavaScript has one number type, so `8.0` comes back as `8`: where the graph the page opened has a
// float at the same place with the same value, it stays a float, and an untouched graph saves
// byte-identical to the file it was opened from.
#include <string>

#include <nlohmann/json.hpp>

namespace fg::studio {

// `original` may be null (a new graph).
std::string canonical_graph_text(nlohmann::ordered_json edited, const nlohmann::ordered_json* original);

// The `editor` block the studio keeps node positions in (version 1): the compiler ignores it.
inline constexpr int kEditorBlockVersion = 1;

}  // namespace fg::studio
