#include "frame_arguments.h"

#include <charconv>
#include <fmt/format.h>

namespace fg {

namespace {
// The whole of `text` as a number, nothing left over ("1.5x" is no number).
template <class T>
bool whole_number(std::string_view text, T& out) {
    const char* end = text.data() + text.size();
    auto [at, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && at == end;
}
}  // namespace

bool parse_knobs(const std::vector<std::string>& texts, std::map<std::string, double>& knobs, std::string& error) {
    for (const auto& text : texts) {
        const auto eq = text.find('=');
        double value = 0.0;
        if (eq == std::string::npos || eq == 0 || !whole_number(std::string_view(text).substr(eq + 1), value)) {
            error = fmt::format("--knob takes name=value, not '{}'", text);
            return false;
        }
        knobs[text.substr(0, eq)] = value;
    }
    return true;
}

bool parse_size(const std::string& text, std::uint32_t max, std::uint32_t& width, std::uint32_t& height,
                std::string& error) {
    const auto x = text.find('x');
    std::uint32_t w = 0, h = 0;
    if (x == std::string::npos || !whole_number(std::string_view(text).substr(0, x), w) ||
        !whole_number(std::string_view(text).substr(x + 1), h) || w == 0 || h == 0 || w > max || h > max) {
        error = fmt::format("--size takes WxH (like 512x512, each 1 to {}), not '{}'", max, text);
        return false;
    }
    width = w;
    height = h;
    return true;
}

bool parse_stereo(const std::string& text, StereoMode& out, std::string& error) {
    if (parse_stereo_mode(text, out)) return true;
    error = fmt::format("--stereo takes reproject, per-eye or naive, not '{}'", text);
    return false;
}

}  // namespace fg
