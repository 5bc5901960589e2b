#include "plot_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <span>
#include <unistd.h>

#include "common/embedded_file.h"

namespace fg {
std::span<const EmbeddedFile> embedded_bench_scripts();   // generated (bench/fg_bench.cmake)
}

namespace fg::bench {

bool run_plot_script(std::string_view script, const std::string& folder) {
    std::string_view text;
    for (const auto& f : embedded_bench_scripts())
        if (f.path == script) text = f.text;
    if (text.empty()) return false;
    const auto copy = std::filesystem::temp_directory_path() / fmt::format("fgplay_{}_{}", getpid(), script);
    std::ofstream(copy, std::ios::binary) << text;
    std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    std::string cmd = fmt::format("{} '{}' '{}'", python, copy.string(), folder);
    std::fflush(stdout);
    bool ok = std::system(cmd.c_str()) == 0;
    std::error_code ignored;
    std::filesystem::remove(copy, ignored);
    return ok;
}

}  // namespace fg::bench
