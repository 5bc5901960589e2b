#pragma once
// How many single-character insertions, deletions or substitutions turn one name into another:
// the measure behind every "did you mean" of the diagnostics.
#include <cstddef>
#include <string_view>

namespace fg {

std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace fg
