#pragma once
// Reads one port declaration ({"name", "type", "doc", "default", "min", "max", "knob", "effect"}),
// shared by node definitions and custom-code nodes in graphs.
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "node_definition.h"

namespace fg {

using ReportError = std::function<void(const std::string& message, const std::string& pointer)>;

std::optional<PortDefinition> read_port_definition(const nlohmann::json& j, const std::string& pointer, bool is_input,
                                                   bool generic_allowed, bool doc_required, const ReportError& error);

}  // namespace fg
