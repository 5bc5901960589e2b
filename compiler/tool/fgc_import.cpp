// fgc import: a Mandelbulber settings file (.fract) as a graph, checked by loading it as fgc
// probe would before it is called done.
#include <filesystem>
#include <fmt/format.h>

#include "analysis/precision_advice.h"
#include "common/atomic_file.h"
#include "fgc_commands.h"
#include "import/mandelbulber_import.h"

namespace fg::fgc {

int import_scene(const Common& c, const std::string& fract, const std::string& output_arg) {
    Diagnostics diag;
    auto text = read_text(fract, diag);
    if (!text) return report(diag, fract);
    auto settings = FractSettings::parse(*text, diag);
    const std::filesystem::path source(fract);
    auto graph = settings ? import_mandelbulber(*settings, source.stem().string(), diag) : std::nullopt;
    if (!graph) return report(diag, fract);
    const std::string output = output_arg.empty() ? std::filesystem::path(source).replace_extension(".json").string() : output_arg;
    auto write = [&] {
        const std::string json_text = graph->dump(2) + "\n";
        return write_file_atomically(output, std::span(reinterpret_cast<const std::uint8_t*>(json_text.data()), json_text.size()), diag);
    };
    if (!write()) return report(diag, fract);
    // The graph must load, as any other: an import that writes what fgc then refuses is a bug here.
    Diagnostics load;
    auto scene = load_cpu_scene(c, output, load);
    if (!scene) {
        diag.append(load);
        diag.error(fmt::format("{} was written but does not load (a bug in the importer)", output));
        return report(diag, fract);
    }
    // Deep zooms are common in Mandelbulber scenes (it computes in double): where float would
    // dissolve the surface, the graph asks for double precision.
    if (float_precision_advice(*scene->ir).too_coarse) {
        (*graph)["scene"]["precision"] = "double";
        diag.note("the camera is too close for float coordinates at its distance from the origin: the graph is set to "
                  "\"precision\": \"double\"");
        if (!write()) return report(diag, fract);
    }
    report(diag, fract);   // the warnings
    fmt::print("{}: wrote {}: {}\n", fract, output, (*graph)["description"].get<std::string>());
    return 0;
}

}  // namespace fg::fgc
