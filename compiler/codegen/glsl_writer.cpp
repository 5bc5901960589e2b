#include "glsl_writer.h"

namespace fg {

void GlslWriter::write(std::string_view text, const SourceOrigin& origin) {
    SourceOrigin o = origin;
    std::size_t start = 0;
    while (start < text.size()) {
        auto end = text.find('\n', start);
        bool has_newline = end != std::string_view::npos;
        if (!has_newline) end = text.size();
        text_.append(text.substr(start, end - start));
        text_.push_back('\n');
        map_.add(++lines_, o);
        if (o.line) ++o.line;
        start = has_newline ? end + 1 : end;
    }
}

}  // namespace fg
