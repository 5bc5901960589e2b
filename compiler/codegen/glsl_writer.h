#pragma once
// Accumulates generated GLSL line by line, recording each line's origin in a source map.
#include <string>
#include <string_view>

#include "source_map.h"

namespace fg {

class GlslWriter {
public:
    // Append text (one or more lines) from `origin`; an origin with a line number advances it
    // per line, so a library body keeps its own line numbers.
    void write(std::string_view text, const SourceOrigin& origin);
    void line(std::string_view text, const SourceOrigin& origin) { write(std::string(text) + "\n", origin); }
    void blank() { line("", {}); }

    const std::string& text() const { return text_; }
    const SourceMap& source_map() const { return map_; }
    int line_count() const { return lines_; }

private:
    std::string text_;
    SourceMap map_;
    int lines_ = 0;
};

}  // namespace fg
