#pragma once
// The fgc subcommands, each a function returning the process exit code.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <memory>

#include "common/diagnostics.h"
#include "cpu/cpu_evaluator.h"
#include "graph/node_library.h"

namespace fg::fgc {

struct Common {
    std::vector<std::string> node_folders;   // extra node libraries (--nodes DIR)
    bool quiet = false;
};

// What the subcommands share: a file's text, the node library with --nodes folders, and the
// diagnostics printed against a file (returns the exit code: 1 when there are errors).
std::optional<std::string> read_text(const std::string& path, Diagnostics& diag);
NodeLibrary library_for(const Common& c, Diagnostics& diag);
int report(const Diagnostics& diag, const std::string& file);

// A graph's IR and its CPU twin with the node library, on the heap together (the twin points into
// the IR, the IR into the library); nullopt with the diagnostics when the graph does not load or a
// node has no twin.
struct CpuScene {
    std::unique_ptr<NodeLibrary> library;
    std::unique_ptr<IrGraph> ir;
    std::optional<CpuEvaluator> evaluator;
};
std::optional<CpuScene> load_cpu_scene(const Common& c, const std::string& graph, Diagnostics& diag);

int check(const Common& c, const std::string& graph);
// precision: "" keeps the graph's scene.precision, else "float" or "double".
int compile(const Common& c, const std::string& graph, const std::string& output, const std::string& glsl_dir,
            bool include_glsl, bool verbose, const std::string& precision = "", bool optimize = true);
int info(const Common& c, const std::string& pack, bool json);
int nodes(const Common& c, const std::string& type, bool markdown);
int probe(const Common& c, const std::string& graph, double x, double y, double z);
// A Mandelbulber settings file as a graph (default output: its name with .json).
int import_scene(const Common& c, const std::string& fract, const std::string& output);

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

struct ExportOptions {
    std::string output;                  // the level set (.vdb); default: the graph's name with .vdb
    std::vector<std::string> meshes;     // meshes of it, by extension: .ply, .obj, .stl
    std::vector<std::string> merge;      // shards' .vdb files to merge instead of sampling a graph
    std::vector<double> box;             // x0 y0 z0 x1 y1 z1; empty: the scene's bounds
    double voxel_size = 0.0;             // 0: the box's longest side / resolution
    int resolution = 256;
    double half_width = 3.0;             // narrow band, voxels each side of the surface
    double adaptivity = 0.0;
    // > 0 grows the shape by this distance; unset: 0 where the distance has an inside (negative
    // values), else half a voxel (the renderer's hit threshold with a voxel for a pixel).
    std::optional<double> offset;
    bool colors = false;                 // PLY vertex colours from the graph's albedo
    int threads = 2;
    std::uint64_t max_memory = 0;        // bytes; 0: half the machine's memory
    std::string shard;                   // "I/N": the I-th of N slabs of the box
    std::vector<std::string> params;     // name=value for the graph's parameters
    bool dry_run = false;                // print the estimate only
    bool quiet = false;                  // no progress bar
};
int export_level_set(const Common& c, const std::string& graph, const ExportOptions& options);

}  // namespace fg::fgc
