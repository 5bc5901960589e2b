#include "user_cache_folder.h"

#include <cstdlib>

namespace fg {

namespace {

std::filesystem::path env_path(const char* name) {
    const char* value = std::getenv(name);
    return value && *value ? std::filesystem::path(value) : std::filesystem::path();
}

}  // namespace

std::filesystem::path user_cache_folder(const char* variable, std::string_view subfolder) {
    std::filesystem::path folder = env_path(variable);
    if (folder == "off") return {};
    if (!folder.empty()) return folder;
    if (auto xdg = env_path("XDG_CACHE_HOME"); !xdg.empty()) folder = xdg / "fractograph";
    else if (auto home = env_path("HOME"); !home.empty()) folder = home / ".cache" / "fractograph";
    else return {};
    return subfolder.empty() ? folder : folder / subfolder;
}

}  // namespace fg
