#pragma once
// Passes already compiled, kept by a hash of their GLSL: an edit recompiles only the passes whose
// code it changed (a literal in the scene changes the passes that evaluate the scene; taa or
// resolve never change). Shared by the threads that compile one graph's passes at once.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string_view>
#include <vector>

#include "common/diagnostics.h"
#include "spirv/reflection.h"

namespace fg {

struct CachedPass {
    std::vector<std::uint32_t> spirv;
    PassReflection reflection;
    Diagnostics diag;   // the compile's warnings, given again on every use
};

class PassCache {
public:
    explicit PassCache(std::size_t capacity = 64) : capacity_(capacity) {}

    // The pass's name and GLSL, and whether the optimiser ran, decide its SPIR-V.
    static std::uint64_t key(std::string_view pass, std::string_view glsl, bool optimized);

    std::optional<CachedPass> find(std::uint64_t key) const;
    // The oldest pass makes room when the cache is full.
    void store(std::uint64_t key, CachedPass pass);
    // Passes stored so far: each one was a run of glslang (and the optimiser).
    std::uint64_t compiles() const;

private:
    mutable std::mutex mutex_;
    std::size_t capacity_;
    std::map<std::uint64_t, CachedPass> passes_;
    std::deque<std::uint64_t> order_;   // oldest first
    std::uint64_t stored_ = 0;
};

}  // namespace fg
