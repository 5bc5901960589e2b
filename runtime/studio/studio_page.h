#pragma once
// The page (studio/ built by Vite), compiled into fgplay so `fgplay studio` needs no source tree.
#include <optional>
#include <string>
#include <string_view>

namespace fg::studio {

struct PageFile {
    std::string_view content;
    const char* mime;
};

// The embedded file for a URL path ("/" is index.html), or nullopt.
std::optional<PageFile> page_file(std::string_view url_path);

}  // namespace fg::studio
