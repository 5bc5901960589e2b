#pragma once
// A file compiled into the binary (node library, pass templates): see cmake/Embed.cmake.
#include <span>
#include <string_view>

namespace fg {

struct EmbeddedFile {
    std::string_view path;  // relative to the folder it was embedded from, e.g. "fractal/mandelbulb.json"
    std::string_view text;
};

}  // namespace fg
