#pragma once
#include <string_view>

namespace fg {

// Port and parameter names become GLSL and C++ identifiers: lower-case letters, digits and '_',
// not starting with a digit, not "fg_"-prefixed (reserved for generated code), and not a keyword
// of either language.
bool is_valid_identifier(std::string_view s);
bool is_reserved_word(std::string_view s);

// Node ids are names in the graph, used in generated code as suffixes: letters, digits, '_', '-'.
bool is_valid_node_id(std::string_view s);

}  // namespace fg
