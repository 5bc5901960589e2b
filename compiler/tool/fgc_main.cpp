// fgc: the Fractograph graph compiler. Graph JSON in, shader pack out.
#include <CLI/CLI.hpp>

#include "command_line.h"
#include "compiler.h"
#include "fgc_commands.h"

int main(int argc, char** argv) {
    CLI::App app{"fgc: compiles Fractograph node graphs (JSON) into shader packs (.fgpack)"};
    app.set_version_flag("--version", std::string("fgc ") + fg::kCompilerVersion);
    app.require_subcommand(1);
    fg::fgc::Common common;
    app.add_option("--nodes", common.node_folders, "extra node library folder (repeatable)")->check(CLI::ExistingDirectory);

    std::string graph, output, glsl_dir, pack, type;
    bool include_glsl = false, verbose = false, json = false, markdown = false;
    double x = 0, y = 0, z = 0;

    auto* check = app.add_subcommand("check", "validate a graph: every problem, with its node and JSON pointer");
    check->add_option("graph", graph, "graph JSON")->required();

    auto* compile = app.add_subcommand("compile", "compile a graph into a shader pack");
    compile->add_option("graph", graph, "graph JSON")->required();
    compile->add_option("-o,--output", output, "pack to write (default: the graph's name with .fgpack)");
    compile->add_option("--emit-glsl", glsl_dir, "also write each pass's generated GLSL into this folder");
    compile->add_flag("--include-glsl", include_glsl, "store the generated GLSL inside the pack (debugging)");
    compile->add_flag("-v,--verbose", verbose, "print stage timings and analysis results");
    bool no_optimize = false;
    compile->add_flag("--no-optimize", no_optimize,
                      "skip the SPIR-V optimiser: a faster compile, for measuring what it saves at run time");
    std::string precision;
    compile->add_option("--precision", precision, "evaluate the scene in float or double (default: the graph's scene.precision)")
        ->check(CLI::IsMember({"float", "double"}));

    auto* info = app.add_subcommand("info", "summarise a pack: effects, passes, knobs, parameters");
    info->add_option("pack", pack, "pack file")->required();
    info->add_flag("--json", json, "print the manifest as JSON");

    auto* nodes = app.add_subcommand("nodes", "list the node library, or document one node type");
    nodes->add_option("type", type, "node type, e.g. fractal.mandelbulb");
    nodes->add_flag("--markdown", markdown, "write the node reference as Markdown (docs/nodes.md)");

    auto* probe = app.add_subcommand("probe", "distance at a point, by the CPU twin in double precision");
    probe->add_option("graph", graph, "graph JSON")->required();
    probe->add_option("x", x)->required();
    probe->add_option("y", y)->required();
    probe->add_option("z", z)->required();

    fg::fgc::CalibrateOptions calib;
    auto* calibrate = app.add_subcommand("calibrate", "measure the derivative bias the graph's fractals need (bubble search) and write it into the graph");
    calibrate->add_option("graph", graph, "graph JSON")->required();
    calibrate->add_option("--samples", calib.samples, "exterior points searched (default 10000)")->check(CLI::Range(1, 10000000));
    calibrate->add_option("--seed", calib.seed, "random seed (same seed, same result)");
    calibrate->add_option("--threads", calib.threads, "CPU threads (default 2)")->check(CLI::Range(1, 256));
    calibrate->add_flag("--dry-run", calib.dry_run, "print the bias, leave the graph as it is");
    calibrate->add_flag("--quiet", calib.quiet, "no progress bar");
    calibrate->add_option("--max-growth", calib.max_growth,
                          "how far the bias may move the visible surface, in hit thresholds (90th percentile near the surface; "
                          "default 2; 0: no limit)")->check(CLI::Range(0.0, 1e12));

    fg::fgc::ExportOptions exp;
    auto* export_cmd = app.add_subcommand("export", "sample the graph's surface into an OpenVDB level set (.vdb) and meshes of it "
                                                    "(PLY, OBJ, STL), or merge the shards of a job array (docs/export.md)");
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
    export_cmd->add_option("--offset", exp.offset, "move the surface out by this distance (negative: in; default: 0, or half a "
                                                   "voxel for a distance without inside)");
    export_cmd->add_flag("--colors", exp.colors, "PLY vertex colours from the graph's albedo");
    export_cmd->add_option("--param", exp.params, "set a parameter, NAME=VALUE (repeatable)");
    export_cmd->add_option("--threads", exp.threads, "CPU threads (default 2)")->check(CLI::Range(1, 1024));
    export_cmd->add_option("--max-memory", exp.max_memory, "refuse to start above this estimated peak, e.g. 8G (default: half the RAM)")
        ->transform(CLI::AsSizeValue(false));
    export_cmd->add_option("--shard", exp.shard, "sample only slab I of N of the box (job arrays); merge them with --merge");
    export_cmd->add_option("--merge", exp.merge, "merge these shards' .vdb files into -o instead of sampling")->expected(1, -1);
    export_cmd->add_flag("--dry-run", exp.dry_run, "print the estimate (voxels, memory, time) and stop");
    export_cmd->add_flag("--quiet", exp.quiet, "no progress bar");

    if (auto failed = fg::cli::parse(app, argc, argv)) return *failed;
    if (*export_cmd) return fg::fgc::export_level_set(common, graph, exp);
    if (*calibrate) return fg::fgc::calibrate(common, graph, calib);
    if (*check) return fg::fgc::check(common, graph);
    if (*compile) return fg::fgc::compile(common, graph, output, glsl_dir, include_glsl, verbose, precision, !no_optimize);
    if (*info) return fg::fgc::info(common, pack, json);
    if (*nodes) return fg::fgc::nodes(common, type, markdown);
    if (*probe) return fg::fgc::probe(common, graph, x, y, z);
    return 2;
}
