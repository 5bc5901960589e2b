#pragma once
// The compiler's stages in one call: load and validate the graph, build the typed IR, fold
// constants, run the analyses (effect set, Lipschitz bound, specialization layout), emit GLSL for
// every pass the pack needs, compile with glslang, optimise and validate with SPIRV-Tools, reflect
// with SPIRV-Cross, and assemble the manifest. `fgc check` stops before writing; `fgc compile`
// writes the pack.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/lipschitz_bound.h"
#include "codegen/pass_assembler.h"
#include "common/diagnostics.h"
#include "graph/node_library.h"
#include "ir/constant_folding.h"
#include "ir/ir_graph.h"
#include "pack/environment_image.h"
#include "pack/manifest.h"
#include "spirv/pass_cache.h"

namespace fg {

inline constexpr const char* kCompilerVersion = "0.1.0";

struct CompileOptions {
    bool optimize = true;          // run the SPIRV-Tools optimiser
    bool include_glsl = false;     // store each pass's GLSL in the pack (debugging)
    // Overrides the graph's scene.precision: true "double", false "float" (fgc compile --precision).
    std::optional<bool> double_precision;
    // Only these passes (say, the ones a preview plays); empty: every pass the graph's effects need.
    std::vector<std::string> only_passes;
    // Passes compiled before, reused where their GLSL is unchanged (and new ones stored); may be null.
    PassCache* cache = nullptr;
    // The folder the graph's files (scene.environment.image) are named relative to; empty: the
    // current one. Confined (a server's), a file must lie inside it: no absolute path, no "..".
    std::string folder;
    bool folder_confined = false;
};

struct CompiledPass {
    AssembledPass source;                 // GLSL and its source map
    std::vector<std::uint32_t> spirv;     // optimised and validated
};

struct StageTimes {
    // Stage times summed over passes (which run in parallel), and the wall-clock total.
    double load_ms = 0, ir_ms = 0, analysis_ms = 0, codegen_ms = 0, glslang_ms = 0, optimize_ms = 0, reflect_ms = 0;
    double wall_ms = 0;
    std::size_t passes_compiled = 0;   // passes glslang compiled; the others came from the cache
    double total_ms() const { return load_ms + ir_ms + analysis_ms + codegen_ms + glslang_ms + optimize_ms + reflect_ms; }
};

struct CompileResult {
    std::string graph_text;
    IrGraph ir;
    FoldingStats folding;
    LipschitzResult lipschitz;
    PackManifest manifest;
    std::vector<CompiledPass> passes;
    StageTimes times;
    bool include_glsl = false;
    std::optional<EnvironmentImage> environment;   // scene.environment's image, read from its file
};

// Front half only: graph -> IR -> analyses. Enough for `fgc check` without a GPU toolchain step.
std::optional<IrGraph> load_and_lower(std::string_view graph_text, const NodeLibrary& library, Diagnostics& diag,
                                      FoldingStats* folding = nullptr);

std::optional<CompileResult> compile_graph(std::string_view graph_text, const NodeLibrary& library,
                                           const CompileOptions& options, Diagnostics& diag);

std::vector<std::uint8_t> pack_bytes(const CompileResult& result);

// std140 offsets of the Params block members, in declaration order, and the block size.
std::vector<std::uint32_t> std140_offsets(const std::vector<ValueType>& members, std::uint32_t& size);

// xxh64 of a text, as 16 hex digits: the graph hash in the manifest.
std::string content_hash(std::string_view text);

}  // namespace fg
