#include "studio/studio_page.h"

#include <span>

#include "common/embedded_file.h"

namespace fg {
std::span<const EmbeddedFile> studio_page_files();
}

namespace fg::studio {

namespace {
const char* mime_of(std::string_view path) {
    auto ends = [&](std::string_view ext) { return path.size() >= ext.size() && path.substr(path.size() - ext.size()) == ext; };
    if (ends(".html")) return "text/html; charset=utf-8";
    if (ends(".js")) return "text/javascript; charset=utf-8";
    if (ends(".css")) return "text/css; charset=utf-8";
    if (ends(".svg")) return "image/svg+xml";
    return "text/plain; charset=utf-8";
}
}  // namespace

std::optional<PageFile> page_file(std::string_view url_path) {
    std::string_view path = url_path == "/" || url_path.empty() ? "index.html" : url_path.substr(1);
    for (const auto& f : studio_page_files())
        if (f.path == path) return PageFile{f.text, mime_of(path)};
    return std::nullopt;
}

}  // namespace fg::studio
