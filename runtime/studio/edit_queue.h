#pragma once
// Edits from the page, compiled one at a time on one thread. An edit that arrives while another
// compiles replaces any edit still waiting: a flood of edits costs at most two compiles, and the
// one that wins is the latest. Whoever asks learns the outcome of the newest finished edit.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

namespace fg::studio {

struct EditOutcome {
    std::uint64_t revision = 0;     // 0: nothing compiled yet
    bool ok = false;
    nlohmann::json diagnostics = nlohmann::json::array();
    double compile_ms = 0.0, pipelines_ms = 0.0;
    // The compile's parts: CPU time summed over the passes compiled at once, and how many passes
    // glslang compiled (the others were unchanged, so they came from the cache).
    double glslang_ms = 0.0, optimize_ms = 0.0;
    std::size_t passes_compiled = 0;
};

class EditQueue {
public:
    using Compile = std::function<EditOutcome(const std::string& graph_text, std::uint64_t revision)>;

    explicit EditQueue(Compile compile);
    ~EditQueue();
    EditQueue(const EditQueue&) = delete;
    EditQueue& operator=(const EditQueue&) = delete;

    // Queues a graph; returns its revision (increasing from 1).
    std::uint64_t submit(std::string graph_text);
    // The newest outcome once one of `revision` or later is done, or after `timeout` whatever is
    // newest (the caller looks at its revision).
    EditOutcome wait_for(std::uint64_t revision, std::chrono::milliseconds timeout);
    EditOutcome latest() const;

    std::uint64_t submitted() const;
    std::uint64_t skipped() const;   // edits replaced before they were compiled
    bool busy() const;

private:
    void work();

    Compile compile_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::optional<std::pair<std::uint64_t, std::string>> waiting_;
    bool compiling_ = false, stopping_ = false;
    std::uint64_t next_revision_ = 1, skipped_ = 0;
    EditOutcome latest_;
    std::thread worker_;
};

}  // namespace fg::studio
