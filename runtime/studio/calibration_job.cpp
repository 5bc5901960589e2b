#include "studio/calibration_job.h"

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/wait.h>

namespace fg::studio {

namespace fs = std::filesystem;

std::string find_fgc() {
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec).parent_path();
    for (const fs::path& candidate : {self / "fgc", self / ".." / "compiler" / "fgc"})
        if (fs::exists(candidate, ec)) return candidate.string();
    return "fgc";
}

CalibrationJob::~CalibrationJob() {
    if (thread_.joinable()) thread_.join();
}

bool CalibrationJob::start(const std::string& graph_text, int samples, std::string& error) {
    std::lock_guard lock(mutex_);
    if (state_ == "running") {
        error = "a calibration is already running";
        return false;
    }
    if (thread_.joinable()) thread_.join();
    state_ = "running";
    log_.clear();
    graph_.clear();
    done_ = total_ = 0;
    thread_ = std::thread([this, graph_text, samples] { run(graph_text, samples); });
    return true;
}

void CalibrationJob::run(std::string graph_text, int samples) {
    auto finish = [&](const std::string& state, const std::string& graph) {
        std::lock_guard lock(mutex_);
        state_ = state;
        graph_ = graph;
    };
    char folder_template[] = "/tmp/fg-studio-calibrate-XXXXXX";
    if (!mkdtemp(folder_template)) return finish("failed", "");
    fs::path folder(folder_template), graph = folder / "graph.json";
    std::ofstream(graph, std::ios::binary) << graph_text;
    std::string command = fmt::format("'{}' calibrate '{}' --samples {} 2>&1", fgc_, graph.string(), samples);
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return finish("failed", "");
    // The progress bar rewrites one line with '\r': "bubble search [###...] 42% 4200/10000 samples".
    static const std::regex progress(R"((\d+)/(\d+) samples)");
    std::string line;
    int c;
    while ((c = std::fgetc(pipe)) != EOF) {
        if (c != '\r' && c != '\n') {
            line += static_cast<char>(c);
            continue;
        }
        std::smatch m;
        std::lock_guard lock(mutex_);
        if (std::regex_search(line, m, progress)) {
            done_ = std::stoull(m[1]);
            total_ = std::stoull(m[2]);
        } else if (!line.empty() && log_.size() < 64 * 1024) {
            log_ += line + "\n";
        }
        line.clear();
    }
    int status = pclose(pipe);
    std::stringstream text;
    text << std::ifstream(graph, std::ios::binary).rdbuf();
    std::error_code ec;
    fs::remove_all(folder, ec);
    bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    finish(ok ? "done" : "failed", ok ? text.str() : "");
}

nlohmann::json CalibrationJob::status() const {
    std::lock_guard lock(mutex_);
    nlohmann::json j{{"state", state_}, {"done", done_}, {"total", total_}, {"log", log_}};
    if (state_ == "done") j["graph"] = graph_;
    return j;
}

}  // namespace fg::studio
