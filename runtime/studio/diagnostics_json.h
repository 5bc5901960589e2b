#pragma once
// Compiler diagnostics as the page shows them: each with its JSON pointer and node id, so the page
// puts the message on the node and the port it names.
#include <nlohmann/json.hpp>

#include "common/diagnostics.h"

namespace fg::studio {

nlohmann::json diagnostics_json(const Diagnostics& diag);

}  // namespace fg::studio
