#include "spirv/pass_cache.h"

#include <xxhash.h>

namespace fg {

std::uint64_t PassCache::key(std::string_view pass, std::string_view glsl, bool optimized) {
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, optimized ? 1 : 0);
    XXH64_update(state, pass.data(), pass.size());
    XXH64_update(state, "\0", 1);
    XXH64_update(state, glsl.data(), glsl.size());
    const std::uint64_t hash = XXH64_digest(state);
    XXH64_freeState(state);
    return hash;
}

std::optional<CachedPass> PassCache::find(std::uint64_t key) const {
    std::lock_guard lock(mutex_);
    auto it = passes_.find(key);
    if (it == passes_.end()) return std::nullopt;
    return it->second;
}

void PassCache::store(std::uint64_t key, CachedPass pass) {
    std::lock_guard lock(mutex_);
    ++stored_;
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
