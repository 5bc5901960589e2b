#pragma once
// SPIRV-Tools: optimise (inlining, dead-code removal, constant folding) and validate a module.
// Specialization constants stay specialisable: the driver folds them at pipeline creation.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"

namespace fg {

std::optional<std::vector<std::uint32_t>> optimize_spirv(const std::string& pass, const std::vector<std::uint32_t>& in,
                                                         Diagnostics& diag);
bool validate_spirv(const std::string& pass, const std::vector<std::uint32_t>& words, Diagnostics& diag);
std::string disassemble_spirv(const std::vector<std::uint32_t>& words);

}  // namespace fg
