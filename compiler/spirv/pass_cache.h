#pragma once
// Passes already compiled, kept by a hash of their GLSL: an edit recompiles only the passes whose
// code it changed (a literal in the scene changes the passes that evaluate the scene; taa or
// resolve never change). Shared by the threads that compile one graph's passes at once. With a
// folder, passes are kept on disk too (pass_cache_file.h), for later processes of the same fgc.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
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
    // The bound on the folder: about two thousand passes of the gallery Mandelbulb's size (30 KiB).
    static constexpr std::uintmax_t kFolderBytes = 64u << 20;

    // `folder` empty: in memory only (user_pass_cache_folder() is the user's folder).
    explicit PassCache(std::size_t capacity = 64, std::filesystem::path folder = {});

    // The pass's name and GLSL, whether the optimiser ran, and the compiler's build decide its SPIR-V.
    static std::uint64_t key(std::string_view pass, std::string_view glsl, bool optimized);

    // From memory, else from the folder (the reflection computed again from the SPIR-V).
    std::optional<CachedPass> find(std::uint64_t key);
    // The oldest pass makes room when the cache is full. Passes whose compile gave warnings are
    // kept in memory only, so that the disk never hides a warning.
    void store(std::uint64_t key, CachedPass pass);
    // Passes stored so far: each one was a run of glslang (and the optimiser).
    std::uint64_t compiles() const;

private:
    void keep(std::uint64_t key, CachedPass pass);   // with mutex_ held

    mutable std::mutex mutex_;
    std::size_t capacity_;
    std::filesystem::path folder_;
    std::map<std::uint64_t, CachedPass> passes_;
    std::deque<std::uint64_t> order_;   // oldest first
    std::uint64_t stored_ = 0;
    std::atomic<std::uint64_t> files_written_{0};
};

}  // namespace fg
