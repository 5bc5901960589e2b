#include "studio/graph_folder.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace fg::studio {

namespace fs = std::filesystem;

GraphFolder::GraphFolder(const fs::path& root) : root_(fs::canonical(root)) {}

std::optional<fs::path> GraphFolder::resolve(const std::string& relative, std::string& error) const {
    if (relative.empty() || relative.size() > 1024) {
        error = "a path inside the studio's folder is required (1 to 1024 characters)";
        return std::nullopt;
    }
    if (relative.find('\0') != std::string::npos || relative.find('\\') != std::string::npos) {
        error = fmt::format("path '{}': no NUL or backslash", relative);
        return std::nullopt;
    }
    fs::path path(relative);
    if (path.is_absolute() || relative.front() == '/' || path.has_root_name()) {
        error = fmt::format("path '{}': absolute paths are refused; give a path inside the studio's folder", relative);
        return std::nullopt;
    }
    for (const auto& part : path)
        if (part == "..") {
            error = fmt::format("path '{}': '..' is refused; the studio reads and writes only inside its folder", relative);
            return std::nullopt;
        }
    // A link inside the folder may still point out of it.
    fs::path full = fs::weakly_canonical(root_ / path);
    auto [end, _] = std::mismatch(root_.begin(), root_.end(), full.begin(), full.end());
    if (end != root_.end()) {
        error = fmt::format("path '{}' leads outside the studio's folder", relative);
        return std::nullopt;
    }
    return full;
}

std::vector<std::string> GraphFolder::list_graphs(std::size_t limit) const {
    std::vector<std::string> out;
    std::error_code ec;
    fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end && out.size() < limit; it.increment(ec)) {
        if (it.depth() > 4) it.disable_recursion_pending();
        const auto& name = it->path().filename().string();
        if (it->is_directory() && (name == "node_modules" || name.starts_with("."))) it.disable_recursion_pending();
        if (!it->is_regular_file() || it->path().extension() != ".json") continue;
        // By the name it has in the folder (a link's own, not its target's), and only what the
        // studio would open: a link that leads out of the folder is left out.
        std::string relative = it->path().lexically_relative(root_).generic_string(), error;
        if (resolve(relative, error)) out.push_back(relative);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::optional<std::string> GraphFolder::read(const std::string& relative, std::string& error) const {
    auto path = resolve(relative, error);
    if (!path) return std::nullopt;
    std::ifstream in(*path, std::ios::binary);
    if (!in || !fs::is_regular_file(*path)) {
        error = fmt::format("'{}': no such graph in the studio's folder", relative);
        return std::nullopt;
    }
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

bool GraphFolder::write(const std::string& relative, const std::string& text, std::string& error) const {
    auto path = resolve(relative, error);
    if (!path) return false;
    if (path->extension() != ".json") {
        error = fmt::format("'{}': the studio saves graphs as .json files", relative);
        return false;
    }
    std::error_code ec;
    fs::create_directories(path->parent_path(), ec);
    fs::path temp = path->string() + ".studio-tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out) {
            error = fmt::format("'{}': cannot write", relative);
            return false;
        }
    }
    fs::rename(temp, *path, ec);
    if (ec) {
        error = fmt::format("'{}': {}", relative, ec.message());
        fs::remove(temp, ec);
        return false;
    }
    return true;
}

}  // namespace fg::studio
