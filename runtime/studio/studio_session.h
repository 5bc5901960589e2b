#pragma once
// What one `fgplay studio` keeps alive between requests, so an edit never pays a cold start: the
// node library, the folder it may touch, the compile queue, the preview (one Vulkan context and the
// newest good pack), node previews and the calibration job. It counts compiles, so a test can
// tell a slider move from a recompile.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "compiler.h"
#include "graph/node_library.h"
#include "spirv/pass_cache_file.h"
#include "studio/calibration_job.h"
#include "studio/edit_queue.h"
#include "studio/graph_folder.h"
#include "studio/node_preview.h"
#include "studio/preview_renderer.h"
#include "vk/context.h"

namespace fg::studio {

struct SessionOptions {
    std::string folder = ".";
    std::uint32_t eye_size = 256;
    std::string fgc;   // empty: find_fgc()
};

class StudioSession {
public:
    StudioSession(const vk::Context& ctx, const SessionOptions& options);

    const NodeLibrary& library() const { return library_; }
    const GraphFolder& folder() const { return folder_; }
    EditQueue& edits() { return *edits_; }
    PreviewRenderer& preview() { return preview_; }
    NodePreviews& node_previews() { return node_previews_; }
    CalibrationJob& calibration() { return calibration_; }

    // Compiles of the preview's graph (node previews count apart).
    std::uint64_t compiles() const { return compiles_; }
    // Every pass compiled this session or kept on disk by an earlier one, by its GLSL: an edit
    // recompiles only the passes it changed.
    PassCache& pass_cache() { return pass_cache_; }

private:
    EditOutcome compile(const std::string& graph_text, std::uint64_t revision);
    std::optional<CompileResult> compile_preview(const std::string& graph_text, bool every_pass, Diagnostics& diag);

    const NodeLibrary& library_;
    GraphFolder folder_;
    PreviewRenderer preview_;
    NodePreviews node_previews_;
    CalibrationJob calibration_;
    std::atomic<std::uint64_t> compiles_{0};
    PassCache pass_cache_{64, user_pass_cache_folder()};
    std::vector<std::string> preview_passes_;   // the programs the playing scene runs; empty: not known yet
    std::unique_ptr<EditQueue> edits_;   // last: its thread uses everything above
};

}  // namespace fg::studio
