#pragma once
// Reads back from optimised SPIR-V (SPIRV-Cross) what the runtime must provide: descriptor
// bindings, push-constant size, specialization constant ids, workgroup size and the member offsets
// of uniform blocks. What the optimiser removed does not appear, so each pass binds only what it
// uses.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "pack/manifest.h"

namespace fg {

struct BlockLayout {
    std::uint32_t size = 0;
    std::map<std::string, std::uint32_t> offsets;   // member name -> byte offset
};

struct PassReflection {
    std::array<std::uint32_t, 3> local_size{1, 1, 1};
    std::vector<ManifestBinding> bindings;
    std::uint32_t push_constant_size = 0;
    std::vector<std::uint32_t> spec_constants;
    std::map<std::string, BlockLayout> uniform_blocks;   // by block type name (FgParams, FgScene...)
};

std::optional<PassReflection> reflect_spirv(const std::string& pass, const std::vector<std::uint32_t>& words,
                                            Diagnostics& diag);

}  // namespace fg
