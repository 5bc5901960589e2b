#pragma once
// The fgc subcommands, each a function returning the process exit code.
#include <cstdint>
#include <string>
#include <vector>

namespace fg::fgc {

struct Common {
    std::vector<std::string> node_folders;   // extra node libraries (--nodes DIR)
    bool quiet = false;
};

int check(const Common& c, const std::string& graph);
// precision: "" keeps the graph's scene.precision, else "float" or "double".
int compile(const Common& c, const std::string& graph, const std::string& output, const std::string& glsl_dir,
            bool include_glsl, bool verbose, const std::string& precision = "", bool optimize = true);
int info(const Common& c, const std::string& pack, bool json);
int nodes(const Common& c, const std::string& type, bool markdown);
int probe(const Common& c, const std::string& graph, double x, double y, double z);

struct CalibrateOptions {
    int samples = 10000;
    std::uint64_t seed = 1;
    int threads = 2;
    bool dry_run = false;
    bool quiet = false;   // no progress bar
    // How far the bias may move the surface the march sees (90th percentile of the estimate's
    // shrink near the surface, in hit thresholds); 0: no limit, remove every overshoot whatever it
    // does to the look.
    double max_growth = 2.0;
};
int calibrate(const Common& c, const std::string& graph, const CalibrateOptions& options);

}  // namespace fg::fgc
