#include "fract_settings.h"

#include <charconv>
#include <fmt/format.h>
#include <sstream>

namespace fg {

namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::optional<FractSettings> FractSettings::parse(const std::string& text, Diagnostics& diag) {
    FractSettings s;
    std::istringstream in(text);
    std::string raw, section;
    for (int line = 1; std::getline(in, raw); ++line) {
        const std::string l = trim(raw);
        if (l.starts_with("# version ")) s.version_ = fract_number(trim(l.substr(10))).value_or(s.version_);
        if (l.empty() || l[0] == '#') continue;
        if (l.front() == '[') {
            if (l.back() != ']') {
                diag.error(fmt::format("line {}: a section header ends with ']': {}", line, l));
                return std::nullopt;
            }
            section = l.substr(1, l.size() - 2);
            s.sections_[section];
            continue;
        }
        // Other sections (animation frames and keyframes, descriptions) are kept by name only.
        if (section != "main_parameters" && !section.starts_with("fractal_")) continue;
        const auto space = l.find_first_of(" \t");
        if (section.empty() || space == std::string::npos || l.back() != ';') {
            diag.error(fmt::format("line {}: expected 'name value;' inside a [section], got: {}", line, l.substr(0, 80)));
            return std::nullopt;
        }
        s.sections_[section][l.substr(0, space)] = {trim(l.substr(space + 1, l.size() - space - 2)), line};
    }
    if (!s.section("main_parameters")) {
        diag.error("no [main_parameters] section: not a Mandelbulber settings file");
        return std::nullopt;
    }
    return s;
}

const FractSettings::Section* FractSettings::section(const std::string& name) const {
    auto it = sections_.find(name);
    return it == sections_.end() ? nullptr : &it->second;
}

const FractValue* FractSettings::find(const std::string& name, const std::string& section_name) const {
    const Section* sec = section(section_name);
    if (!sec) return nullptr;
    auto it = sec->find(name);
    return it == sec->end() ? nullptr : &it->second;
}

std::optional<double> fract_number(const std::string& text) {
    std::string t = text;
    for (auto& ch : t)
        if (ch == ',') ch = '.';   // a decimal comma
    double x = 0.0;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return x;
}

std::optional<glm::dvec3> fract_vector(const std::string& text) {
    std::istringstream in(text);
    std::string part;
    glm::dvec3 v(0.0);
    for (int i = 0; i < 3; ++i) {
        if (!(in >> part)) return std::nullopt;
        auto x = fract_number(part);
        if (!x) return std::nullopt;
        v[i] = *x;
    }
    return in >> part ? std::nullopt : std::optional<glm::dvec3>(v);
}

std::optional<bool> fract_bool(const std::string& text) {
    if (text == "true") return true;
    if (text == "false") return false;
    return std::nullopt;
}

}  // namespace fg
