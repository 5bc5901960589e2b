#include "diagnostics.h"

#include <algorithm>
#include <fmt/format.h>

namespace fg {

void Diagnostics::error(std::string message, std::string pointer, std::string node_id) {
    items_.push_back({Severity::Error, std::move(message), std::move(node_id), std::move(pointer), {}, {}});
}
void Diagnostics::warning(std::string message, std::string pointer, std::string node_id) {
    items_.push_back({Severity::Warning, std::move(message), std::move(node_id), std::move(pointer), {}, {}});
}
void Diagnostics::note(std::string message, std::string pointer, std::string node_id) {
    items_.push_back({Severity::Note, std::move(message), std::move(node_id), std::move(pointer), {}, {}});
}
void Diagnostics::append(const Diagnostics& other) {
    items_.insert(items_.end(), other.items_.begin(), other.items_.end());
}
bool Diagnostics::has_errors() const { return error_count() > 0; }
std::size_t Diagnostics::error_count() const {
    return static_cast<std::size_t>(std::count_if(items_.begin(), items_.end(),
                                                  [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

std::string format_diagnostic(const Diagnostic& d, const std::string& file) {
    const char* sev = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note";
    std::string where;
    if (!d.pointer.empty()) where += d.pointer;
    if (d.byte) where += (where.empty() ? "" : " ") + fmt::format("byte {}", *d.byte);
    if (!d.node_id.empty()) where += (where.empty() ? "" : " ") + fmt::format("(node '{}')", d.node_id);
    std::string line = file.empty() ? "" : file + ": ";
    line += fmt::format("{}: ", sev);
    if (!where.empty()) line += where + ": ";
    line += d.message;
    if (!d.context.empty()) {
        std::size_t start = 0;
        while (start < d.context.size()) {
            auto end = d.context.find('\n', start);
            if (end == std::string::npos) end = d.context.size();
            line += "\n    " + d.context.substr(start, end - start);
            start = end + 1;
        }
    }
    return line;
}

std::string Diagnostics::format(const std::string& file) const {
    std::string out;
    for (const auto& d : items_) out += format_diagnostic(d, file) + "\n";
    return out;
}

}  // namespace fg
