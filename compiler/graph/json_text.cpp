#include "json_text.h"

#include <fmt/format.h>
#include <set>
#include <vector>

namespace fg {

std::string describe_offset(std::string_view text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return fmt::format("line {}, column {}", line, column);
}

namespace {

// Tracks where the parser is, so a repeated key can be reported with its JSON pointer.
struct KeyTracker {
    struct Level {
        bool is_object = false;
        std::size_t index = 0;      // arrays: next element index
        std::string key;            // objects: current key
        std::set<std::string> seen;
    };
    std::vector<Level> stack;
    std::vector<std::string> duplicates;  // pointers

    std::string pointer() const {
        std::string p;
        for (const auto& l : stack) {
            if (l.is_object) {
                if (!l.key.empty()) p += "/" + l.key;
            } else {
                p += fmt::format("/{}", l.index);
            }
        }
        return p;
    }
    // A value finished inside an array: move to the next index.
    void value_done() {
        if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
    }
};

}  // namespace

namespace {
// Deeper documents are refused: copying and walking nested JSON recurses, and no graph or
// manifest needs more than a handful of levels.
constexpr int kMaxDepth = 64;
struct TooDeep {
    std::string pointer;
};
}  // namespace

std::optional<nlohmann::json> parse_json_text(std::string_view text, Diagnostics& diag) {
    bool blank = true;
    for (char c : text)
        if (!(c == ' ' || c == '\n' || c == '\r' || c == '\t')) blank = false;
    if (blank) {
        diag.error("the file is empty: expected a JSON object");
        return std::nullopt;
    }
    KeyTracker keys;
    using nlohmann::json;
    json::parser_callback_t cb = [&keys](int depth, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start: {
                if (depth >= kMaxDepth) throw TooDeep{keys.pointer()};
                KeyTracker::Level l;
                l.is_object = event == json::parse_event_t::object_start;
                keys.stack.push_back(std::move(l));
                break;
            }
            case json::parse_event_t::key: {
                auto& l = keys.stack.back();
                l.key = parsed.get<std::string>();
                if (!l.seen.insert(l.key).second) keys.duplicates.push_back(keys.pointer());
                break;
            }
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                keys.stack.pop_back();
                keys.value_done();
                break;
            case json::parse_event_t::value:
                keys.value_done();
                break;
        }
        return true;
    };
    try {
        auto j = json::parse(text.begin(), text.end(), cb, true, false);
        for (const auto& p : keys.duplicates) diag.error("key given twice; JSON keeps only the last, so say it once", p);
        if (!keys.duplicates.empty()) return std::nullopt;
        return j;
    } catch (const TooDeep& deep) {
        diag.error(fmt::format("nested more than {} levels deep", kMaxDepth), deep.pointer);
    } catch (const json::parse_error& e) {
        std::string what = e.what();
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line 1, column 2: ".
        auto colon = what.find(": ", what.find("parse error"));
        std::string reason = colon == std::string::npos ? what : what.substr(colon + 2);
        bool truncated = e.byte >= text.size();
        diag.error(fmt::format("{}not valid JSON at {}: {}", truncated ? "the file ends early; " : "",
                               describe_offset(text, e.byte == 0 ? 0 : e.byte - 1), reason));
    } catch (const json::out_of_range& e) {
        // A number too large for a double (1e999): report where it is; it would be infinite.
        std::string what = e.what();
        auto quote = what.find('\'');
        std::string token = quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
        auto at = token.empty() ? std::string_view::npos : text.find(token);
        diag.error(fmt::format("number {} at {} is out of range: literals must be finite", token,
                               at == std::string_view::npos ? "?" : describe_offset(text, at)));
    } catch (const json::exception& e) {
        std::string what = e.what();
        auto bracket = what.find("] ");
        diag.error(fmt::format("not valid JSON: {}", bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
    return std::nullopt;
}

}  // namespace fg
