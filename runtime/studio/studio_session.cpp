#include "studio/studio_session.h"

#include <chrono>

#include "graph/body_literal_params.h"
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

// The preview needs its passes soon, not at their fastest: it compiles only the passes it plays,
// and without the optimiser, which on lavapipe costs more time than it saves (docs/studio.md). An
// export compiles the whole pack, optimised.
std::optional<CompileResult> StudioSession::compile_preview(const std::string& graph_text, bool every_pass,
                                                            Diagnostics& diag) {
    CompileOptions options;
    options.optimize = false;
    options.cache = &pass_cache_;
    options.folder = folder_.root().string();
    options.folder_confined = true;
    if (!every_pass) options.only_passes = preview_passes_;
    // A formula's numbers as uniforms: editing one compiles nothing.
    return compile_graph(with_body_literals_as_params(graph_text, library_), library_, options, diag);
}

EditOutcome StudioSession::compile(const std::string& graph_text, std::uint64_t revision) {
    EditOutcome out;
    Diagnostics diag;
    ++compiles_;
    // An edit that makes the scene need a pass the last one did not (an effect switched on) finds it
    // missing when the pipelines are built: then every pass is compiled.
    for (bool every_pass : {preview_passes_.empty(), true}) {
        Diagnostics attempt;
        auto start = std::chrono::steady_clock::now();
        auto result = compile_preview(graph_text, every_pass, attempt);
        std::optional<Pack> pack;
        if (result) pack = read_pack(pack_bytes(*result), attempt);
        out.compile_ms += ms_since(start);
        if (result) {
            out.glslang_ms += result->times.glslang_ms;
            out.optimize_ms += result->times.optimize_ms;
            out.passes_compiled += result->times.passes_compiled;
        }
        if (!pack) {
            diag.append(attempt);
            break;
        }
        start = std::chrono::steady_clock::now();
        try {
            auto scene = preview_.prepare(std::move(*pack), revision);
            out.pipelines_ms += ms_since(start);
            preview_passes_ = {"probe"};
            for (const auto& pass : scene->renderer->graph().passes()) preview_passes_.push_back(pass.program);
            preview_.show(std::move(scene));
            diag.append(attempt);
            out.ok = true;
            break;
        } catch (const std::exception& e) {
            out.pipelines_ms += ms_since(start);
            if (every_pass) {
                attempt.error(e.what());
                diag.append(attempt);
                break;
            }
        }
    }
    out.diagnostics = diagnostics_json(diag);
    return out;
}

}  // namespace fg::studio
