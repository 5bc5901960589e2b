#pragma once
// The node library as the page's palette reads it: every type with its category (namespace), docs,
// context and typed ports, so the page draws nodes and colours ports without a second copy.
#include <nlohmann/json.hpp>

#include "graph/node_library.h"

namespace fg::studio {

nlohmann::json node_catalog_json(const NodeLibrary& library);

}  // namespace fg::studio
