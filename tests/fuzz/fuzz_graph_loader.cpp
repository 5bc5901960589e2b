// libFuzzer target: any bytes, read as graph JSON text, must give a graph or diagnostics, never a
// crash, a sanitizer report or an exception (load_graph promises that nothing throws).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "graph/graph_loader.h"
#include "graph/node_library.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        fg::Diagnostics diag;
        auto graph = fg::load_graph(text, fg::NodeLibrary::builtin(), diag);
        // A refused graph says why; an accepted one has no errors.
        if (!graph && !diag.has_errors()) {
            std::fprintf(stderr, "load_graph refused the input without an error\n");
            std::abort();
        }
        if (graph && diag.has_errors()) {
            std::fprintf(stderr, "load_graph accepted the input but reported errors:\n%s\n", diag.format().c_str());
            std::abort();
        }
        (void)diag.format();  // formatting every diagnostic must be safe too
    } catch (const std::exception& e) {
        std::fprintf(stderr, "load_graph threw: %s\n", e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "load_graph threw a non-std exception\n");
        std::abort();
    }
    return 0;
}
