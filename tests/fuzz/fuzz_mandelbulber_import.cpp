// libFuzzer target: any bytes, read as a Mandelbulber settings file, must give a graph or
// diagnostics naming why not, never a crash, a sanitizer report or an exception.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "import/mandelbulber_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        fg::Diagnostics diag;
        auto settings = fg::FractSettings::parse(text, diag);
        auto graph = settings ? fg::import_mandelbulber(*settings, "fuzz", diag) : std::nullopt;
        if (!graph && !diag.has_errors()) {
            std::fprintf(stderr, "the import refused the input without an error\n");
            std::abort();
        }
        if (graph) (void)graph->dump();
        (void)diag.format();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "the import threw: %s\n", e.what());
        std::abort();
    }
    return 0;
}
