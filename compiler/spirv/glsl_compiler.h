#pragma once
// GLSL -> SPIR-V with glslang (Vulkan 1.2, SPIR-V 1.5). Errors in generated code are reported
// against what produced the line: a graph node (custom code), a library body or a pass template,
// with the generated line shown as context.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "codegen/source_map.h"
#include "common/diagnostics.h"

namespace fg {

std::optional<std::vector<std::uint32_t>> compile_glsl(const std::string& pass, const std::string& glsl,
                                                       const SourceMap& map, Diagnostics& diag);

// Turns one glslang log line ("ERROR: 0:12: 'x' : undeclared identifier") into a diagnostic
// through the source map. Exposed for tests.
std::optional<Diagnostic> map_glslang_message(const std::string& log_line, const std::string& pass,
                                              const std::string& glsl, const SourceMap& map);

}  // namespace fg
