#pragma once
// `fgc calibrate` run from the page: the graph being edited is written to a private temporary
// folder (never into the studio's folder), fgc runs on it in the background with its progress
// read from its output, and the calibrated graph comes back to the page, which decides to keep it.
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

namespace fg::studio {

class CalibrationJob {
public:
    explicit CalibrationJob(std::string fgc_path) : fgc_(std::move(fgc_path)) {}
    ~CalibrationJob();

    // False (with `error`) while one is running.
    bool start(const std::string& graph_text, int samples, std::string& error);
    // {"state": "idle|running|done|failed", "done", "total", "log", "graph" (when done)}
    nlohmann::json status() const;

private:
    void run(std::string graph_text, int samples);

    std::string fgc_;
    mutable std::mutex mutex_;
    std::thread thread_;
    std::string state_ = "idle", log_, graph_;
    std::uint64_t done_ = 0, total_ = 0;
};

// The fgc next to this program, or the build tree's, or the one on PATH.
std::string find_fgc();

}  // namespace fg::studio
