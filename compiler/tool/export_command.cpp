#include "export_command.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>

namespace fg::fgc {

CLI::App* add_export_placeholder(CLI::App& app) {
    auto* cmd = app.add_subcommand("export", kExportSummary);
    cmd->prefix_command();   // everything after `export` is fgc-export's to parse
    cmd->set_help_flag();    // so is --help
    return cmd;
}

int run_export_program(char** argv) {
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string beside = ec ? std::string() : (self.parent_path() / "fgc-export").string();
    // argv[0] stays fgc's, so fgc-export's messages and help name `fgc export`.
    if (!beside.empty() && ::access(beside.c_str(), X_OK) == 0)
        ::execv(beside.c_str(), argv);
    else
        ::execvp("fgc-export", argv);
    fmt::print(stderr, "fgc export: error: cannot start fgc-export (looked beside fgc, in {}, and on PATH): {}\n",
               beside.empty() ? "?" : std::filesystem::path(beside).parent_path().string(), std::strerror(errno));
    return 127;
}

CLI::App* add_export_command(CLI::App& app, std::string& graph, ExportOptions& exp) {
    auto* export_cmd = app.add_subcommand("export", kExportSummary);
    export_cmd->add_option("graph", graph, "graph JSON (not with --merge)");
    export_cmd->add_option("-o,--output", exp.output, "level set to write (default: the graph's name with .vdb)");
    export_cmd->add_option("--mesh", exp.meshes, "also write a mesh of the surface: .ply, .obj or .stl (repeatable)");
    export_cmd->add_option("--box", exp.box, "region to export, x0,y0,z0,x1,y1,z1 (default: the cube around /scene/bounds)")
        ->expected(6)->delimiter(',');
    export_cmd->add_option("--resolution", exp.resolution, "voxels across the box's longest side (default 256)")
        ->check(CLI::Range(8, 1 << 20));
    export_cmd->add_option("--voxel-size", exp.voxel_size, "voxel edge in scene units (overrides --resolution)")
        ->check(CLI::PositiveNumber);
    export_cmd->add_option("--band", exp.half_width, "narrow band half-width in voxels (default 3)")->check(CLI::Range(1.0, 64.0));
    export_cmd->add_option("--adaptivity", exp.adaptivity, "mesh simplification, 0 (every voxel) to 1 (fewest triangles; default 0)")
        ->check(CLI::Range(0.0, 1.0));
    export_cmd->add_option("--offset", exp.offset, "move the whole surface out by this distance (negative: in; default 0), on top "
                                                   "of the half voxel each part without an inside is taken at");
    export_cmd->add_flag("--colors", exp.colors, "PLY vertex colours from the graph's albedo");
    export_cmd->add_option("--param", exp.params, "set a parameter, NAME=VALUE (repeatable)");
    export_cmd->add_option("--threads", exp.threads, "CPU threads (default 2)")->check(CLI::Range(1, 1024));
    export_cmd->add_option("--max-memory", exp.max_memory, "refuse to start above this estimated peak, e.g. 8G (default: half the RAM)")
        ->transform(CLI::AsSizeValue(false));
    export_cmd->add_option("--shard", exp.shard, "sample only slab I of N of the box (job arrays); merge them with --merge");
    export_cmd->add_option("--merge", exp.merge, "merge these shards' .vdb files into -o instead of sampling")->expected(1, -1);
    export_cmd->add_flag("--dry-run", exp.dry_run, "print the estimate (voxels, memory, time) and stop");
    export_cmd->add_flag("--quiet", exp.quiet, "no progress bar");
    return export_cmd;
}

}  // namespace fg::fgc
