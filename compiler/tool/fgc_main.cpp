// fgc: the Fractograph graph compiler. Graph JSON in, shader pack out.
#include <CLI/CLI.hpp>

#include "command_line.h"
#include "compiler.h"
#include "export_command.h"
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

    std::string fract;
    auto* import_cmd = app.add_subcommand("import", "make a graph of a Mandelbulber settings file (.fract): camera, formula or hybrid, "
                                                    "iterations; what cannot be imported is named (docs/formulas.md)");
    import_cmd->add_option("scene", fract, "Mandelbulber settings file")->required();
    import_cmd->add_option("-o,--output", output, "graph to write (default: the scene's name with .json)");

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

    // Export runs in its own program, fgc-export, beside this one: OpenVDB's 69,000 symbol bindings
    // would otherwise cost every fgc command about 25 ms at start. It takes this command line whole.
    auto* export_cmd = fg::fgc::add_export_placeholder(app);

    if (auto failed = fg::cli::parse(app, argc, argv)) return *failed;
    if (*export_cmd) return fg::fgc::run_export_program(argv);
    if (*calibrate) return fg::fgc::calibrate(common, graph, calib);
    if (*check) return fg::fgc::check(common, graph);
    if (*compile) return fg::fgc::compile(common, graph, output, glsl_dir, include_glsl, verbose, precision, !no_optimize);
    if (*info) return fg::fgc::info(common, pack, json);
    if (*nodes) return fg::fgc::nodes(common, type, markdown);
    if (*probe) return fg::fgc::probe(common, graph, x, y, z);
    if (*import_cmd) return fg::fgc::import_scene(common, fract, output);
    return 2;
}
