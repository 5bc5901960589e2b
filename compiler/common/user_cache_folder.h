#pragma once
// Where Fractograph keeps what it may throw away: the Vulkan pipeline cache, compiled passes.
#include <filesystem>
#include <string_view>

namespace fg {

// The folder named by the environment variable `variable` ("off" disables the cache), else
// $XDG_CACHE_HOME/fractograph/`subfolder`, else ~/.cache/fractograph/`subfolder`. Empty when the
// cache is off or there is no home.
std::filesystem::path user_cache_folder(const char* variable, std::string_view subfolder = {});

}  // namespace fg
