#pragma once
// Where the preview's pack comes from: a .fgpack file, or a graph JSON compiled in-process. With
// --watch the graph is recompiled in the background whenever it is saved; the new pack (and its
// pipelines, built on that thread too) replaces the playing one only when it is ready, and a
// compile error is reported while the old pack keeps playing.
#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "frame/frame_executor.h"
#include "pack/pack_reader.h"
#include "spirv/pass_cache.h"
#include "spirv/pass_cache_file.h"

namespace fg::desktop {

struct LoadedPack {
    std::unique_ptr<Pack> pack;
    std::unique_ptr<FrameExecutor> executor;
    double compile_ms = 0.0, pipelines_ms = 0.0;
};

// Builds the frame graph and its pipelines for `pack`.
using ExecutorFactory = std::function<std::unique_ptr<FrameExecutor>(const Pack&)>;

class PackSource {
public:
    PackSource(std::string path, bool watch, ExecutorFactory factory);
    ~PackSource();

    // The first pack, synchronously; throws std::runtime_error with the diagnostics.
    LoadedPack load_now();

    // Polls the file (at most every 200 ms) and any compile in flight. Returns a new pack when one
    // is ready; sets `error` when a compile failed (the caller keeps what it plays).
    std::optional<LoadedPack> poll(std::string& error);
    bool compiling() const { return pending_.valid(); }

private:
    struct Outcome {
        std::optional<LoadedPack> loaded;
        std::string error;
    };
    Outcome build() const;

    std::string path_;
    bool watch_ = false, is_graph_ = false;
    ExecutorFactory factory_;
    // Passes compiled before, in this run or kept on disk by an earlier one: a save recompiles only
    // the passes whose code it changed. Shared with the compile thread, and thread-safe.
    std::unique_ptr<PassCache> pass_cache_ = std::make_unique<PassCache>(64, user_pass_cache_folder());
    std::filesystem::file_time_type stamp_{};
    std::chrono::steady_clock::time_point last_check_{};
    std::future<Outcome> pending_;
};

}  // namespace fg::desktop
