#pragma once
// Parse JSON text for a graph or a node definition, turning every way it can be broken (empty,
// not JSON, truncated, a number out of range, a key given twice) into a diagnostic with a line and
// column instead of an exception.
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"

namespace fg {

std::optional<nlohmann::json> parse_json_text(std::string_view text, Diagnostics& diag);

// "line 3, column 14" for a byte offset into text.
std::string describe_offset(std::string_view text, std::size_t byte);

}  // namespace fg
