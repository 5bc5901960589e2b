#pragma once
// The pack manifest: what the runtime needs to play a pack without knowing the graph. Written by
// the compiler as JSON (MANI chunk), read back and checked for consistency by the pack reader.
#include <array>
#include <map>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/diagnostics.h"
#include "common/effects.h"
#include "common/value_type.h"
#include "graph/scene_settings.h"

namespace fg {

inline constexpr int kManifestVersion = 1;

// A graph parameter: a member of the Params uniform block (offsets from SPIR-V reflection).
struct ManifestParam {
    std::string name;
    ValueType type = ValueType::Float;
    Constant value;
    std::optional<double> min, max;
    std::uint32_t offset = 0;
    std::string doc;
};

struct ManifestBinding {
    std::uint32_t set = 0;
    std::uint32_t binding = 0;
    std::string kind;   // uniform_buffer, storage_buffer, storage_image, sampled_image
    std::string name;   // the block or image name in the shader
    // What the shader may do with it, from its qualifiers: "read" (readonly, uniform blocks),
    // "write" (writeonly) or "read_write". Packs from before it was recorded read as "read_write".
    std::string access = "read_write";
    // Storage images: the declared format ("rgba16f"), which the bound image must have. Empty in
    // packs from before it was recorded.
    std::string format;
};

// An accuracy knob as a specialization constant. Ids start at 1: id 0 is never used.
struct ManifestSpecConstant {
    std::uint32_t id = 0;
    std::string name;         // "epsilon", "bias.bulb", "iterations.bulb"
    ValueType type = ValueType::Float;   // float, int or bool
    double value = 0;         // the default the pack was compiled with
    std::optional<double> min, max;
    std::string doc;
};

struct ManifestPass {
    std::string name;                                  // also the SPRV chunk name
    std::array<std::uint32_t, 3> local_size{1, 1, 1};
    std::vector<ManifestBinding> bindings;
    std::uint32_t push_constant_size = 0;
    std::vector<std::uint32_t> spec_constants;         // knob ids the pass's SPIR-V declares
    std::vector<std::uint32_t> dispatch_constants;     // and dispatch constant ids (common/spec_constants.h)
};

struct ManifestFractal {
    std::string node;                  // graph node id
    std::string type;                  // node type
    std::string running_derivative;    // the guarded formula, for documentation
    std::uint32_t bias_spec = 0;       // spec constant id of the bias (0: bound to a param)
    std::uint32_t iterations_spec = 0; // spec constant id of the iterations (0: a param)
};

struct PackManifest {
    int version = kManifestVersion;
    std::string name;
    std::string compiler;              // "fgc 0.1.0"
    std::string graph_hash;            // xxh64 of the source graph text, hex
    EffectSet effects;
    std::uint32_t params_size = 0;     // bytes of the Params block (0: no params)
    std::vector<ManifestParam> params;
    std::vector<ManifestPass> passes;
    std::vector<ManifestSpecConstant> spec_constants;
    double lipschitz_bound = 1.0;      // static bound of the distance's Lipschitz constant
    bool lipschitz_exact = true;       // false: some rule was unknown and a fallback was used
    std::vector<std::string> lipschitz_notes;
    std::vector<ManifestFractal> fractals;
    // The scene repeats with this period on every axis (analysis/periodicity.h); absent in packs
    // from before it was recorded and in scenes that do not repeat.
    std::optional<std::array<double, 3>> period;
    SceneSettings scene;               // decoded once, when the manifest is read
    std::map<std::string, std::uint32_t> uniform_blocks;  // block type name -> size, from reflection
    // "double": the scene runs in double around the camera and needs shaderFloat64. Packs written
    // before the field existed are "float".
    std::string precision = "float";
    // The distance reads input.time: the scene moves by itself, so nothing one frame's march proves
    // holds for the next. Packs from before it was recorded cannot run with this runtime (their
    // frame block is smaller), so none is misread as static.
    bool animated = false;

    const ManifestPass* find_pass(const std::string& name) const;
    const ManifestSpecConstant* find_spec(const std::string& name) const;
    const ManifestSpecConstant* find_spec(std::uint32_t id) const;
    const ManifestParam* find_param(const std::string& name) const;
};

nlohmann::json manifest_to_json(const PackManifest& m);
// Reads and checks a manifest; problems are reported with their pointer inside the manifest.
std::optional<PackManifest> manifest_from_json(const nlohmann::json& j, Diagnostics& diag);

}  // namespace fg
