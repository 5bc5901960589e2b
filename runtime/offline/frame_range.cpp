#include "frame_range.h"

#include <charconv>
#include <fmt/format.h>

namespace fg {

namespace {
bool read_int(const std::string& s, int& out) {
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}
}  // namespace

std::optional<FrameRange> parse_frame_range(const std::string& text, int frame_count, std::string& error) {
    FrameRange r{0, frame_count};
    auto colon = text.find(':');
    bool ok = true;
    if (colon == std::string::npos) {
        ok = read_int(text, r.begin);
        r.end = r.begin + 1;
    } else {
        std::string a = text.substr(0, colon), b = text.substr(colon + 1);
        if (!a.empty()) ok = read_int(a, r.begin);
        if (ok && !b.empty()) ok = read_int(b, r.end);
    }
    if (!ok) {
        error = fmt::format("--frames takes A:B (frames A to B-1), A:, :B or A, not '{}'", text);
        return std::nullopt;
    }
    if (r.begin < 0 || r.begin >= r.end || r.end > frame_count) {
        error = fmt::format("--frames {} is not a non-empty range inside the path's frames 0:{}", text, frame_count);
        return std::nullopt;
    }
    return r;
}

bool parse_shard(const std::string& text, int& index, int& count, std::string& error) {
    auto slash = text.find('/');
    if (slash == std::string::npos || !read_int(text.substr(0, slash), index) || !read_int(text.substr(slash + 1), count) ||
        count < 1 || index < 0 || index >= count) {
        error = fmt::format("--shard takes I/N with 0 <= I < N (a job array's task index and size), not '{}'", text);
        return false;
    }
    return true;
}

FrameRange shard_of(const FrameRange& range, int index, int count) {
    long long n = range.size();
    return {range.begin + static_cast<int>(n * index / count), range.begin + static_cast<int>(n * (index + 1) / count)};
}

}  // namespace fg
