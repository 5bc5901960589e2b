#pragma once
// The folder the studio was opened on: the only place it reads or writes. Paths come from the page
// relative to it; absolute paths, `..` and links that lead outside are refused with the reason.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fg::studio {

class GraphFolder {
public:
    explicit GraphFolder(const std::filesystem::path& root);

    const std::filesystem::path& root() const { return root_; }

    // The file a relative path names inside the folder, or nullopt with `error`.
    std::optional<std::filesystem::path> resolve(const std::string& relative, std::string& error) const;

    // Graph files (*.json) under the folder, relative, sorted; at most `limit`.
    std::vector<std::string> list_graphs(std::size_t limit = 2000) const;

    std::optional<std::string> read(const std::string& relative, std::string& error) const;
    // Writes through a temporary file beside the target, so a failed write leaves the old file.
    bool write(const std::string& relative, const std::string& text, std::string& error) const;

private:
    std::filesystem::path root_;   // canonical
};

}  // namespace fg::studio
