#include "studio/studio_session.h"

#include <chrono>

#include "compiler.h"
#include "studio/diagnostics_json.h"

namespace fg::studio {

namespace {
double ms_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

StudioSession::StudioSession(const vk::Context& ctx, const SessionOptions& options)
    : library_(NodeLibrary::builtin()),
      folder_(options.folder),
      preview_(ctx, options.eye_size),
      node_previews_(ctx, library_),
      calibration_(options.fgc.empty() ? find_fgc() : options.fgc),
      edits_(std::make_unique<EditQueue>([this](const std::string& text, std::uint64_t revision) {
          return compile(text, revision);
      })) {}

EditOutcome StudioSession::compile(const std::string& graph_text, std::uint64_t revision) {
    EditOutcome out;
    Diagnostics diag;
    auto start = std::chrono::steady_clock::now();
    ++compiles_;
    auto result = compile_graph(graph_text, library_, {}, diag);
    std::optional<Pack> pack;
    if (result) pack = read_pack(pack_bytes(*result), diag);
    out.compile_ms = ms_since(start);
    if (pack) {
        start = std::chrono::steady_clock::now();
        try {
            preview_.show(preview_.prepare(std::move(*pack), revision));
            out.ok = true;
        } catch (const std::exception& e) {
            diag.error(e.what());
        }
        out.pipelines_ms = ms_since(start);
    }
    out.diagnostics = diagnostics_json(diag);
    return out;
}

}  // namespace fg::studio
