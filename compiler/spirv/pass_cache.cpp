#include "spirv/pass_cache.h"

#include <system_error>

#include <xxhash.h>

#include "spirv/pass_cache_file.h"

namespace fg {

// Without a build id nothing says which fgc wrote a file: keep passes in memory only.
PassCache::PassCache(std::size_t capacity, std::filesystem::path folder)
    : capacity_(capacity), folder_(toolchain_id().empty() ? std::filesystem::path() : std::move(folder)) {}

std::uint64_t PassCache::key(std::string_view pass, std::string_view glsl, bool optimized) {
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, optimized ? 1 : 0);
    XXH64_update(state, toolchain_id().data(), toolchain_id().size() + 1);   // with its '\0'
    XXH64_update(state, pass.data(), pass.size());
    XXH64_update(state, "\0", 1);
    XXH64_update(state, glsl.data(), glsl.size());
    const std::uint64_t hash = XXH64_digest(state);
    XXH64_freeState(state);
    return hash;
}

std::optional<CachedPass> PassCache::find(std::uint64_t key) {
    {
        std::lock_guard lock(mutex_);
        if (auto it = passes_.find(key); it != passes_.end()) return it->second;
    }
    if (folder_.empty()) return std::nullopt;
    const auto file = pass_file(folder_, key);
    auto spirv = read_pass_file(file, key);
    if (!spirv) return std::nullopt;
    Diagnostics ignored;   // SPIR-V that cannot be reflected is compiled again, and its file replaced
    auto reflection = reflect_spirv(file.filename().string(), *spirv, ignored);
    if (!reflection) return std::nullopt;
    // A use counts as a write for trim_pass_folder: the passes in use stay.
    std::error_code error;
    std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), error);
    CachedPass pass{std::move(*spirv), std::move(*reflection), {}};
    std::lock_guard lock(mutex_);
    keep(key, pass);
    return pass;
}

void PassCache::store(std::uint64_t key, CachedPass pass) {
    // The folder is trimmed at the first write of a process and every 32 after it: a long studio
    // session stays within its bound, and a run that compiles nothing lists no folder.
    if (!folder_.empty() && pass.diag.empty() && write_pass_file(pass_file(folder_, key), key, pass.spirv) &&
        files_written_++ % 32 == 0)
        trim_pass_folder(folder_, kFolderBytes);
    std::lock_guard lock(mutex_);
    ++stored_;
    keep(key, std::move(pass));
}

void PassCache::keep(std::uint64_t key, CachedPass pass) {
    if (passes_.insert_or_assign(key, std::move(pass)).second) order_.push_back(key);
    while (passes_.size() > capacity_) {
        passes_.erase(order_.front());
        order_.pop_front();
    }
}

std::uint64_t PassCache::compiles() const {
    std::lock_guard lock(mutex_);
    return stored_;
}

}  // namespace fg
