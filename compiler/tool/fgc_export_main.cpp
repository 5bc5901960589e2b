// fgc-export: `fgc export` in a program of its own, the one fgc command that needs OpenVDB (fgc
// hands it its command line whole, so the two parse the same words).
#include <CLI/CLI.hpp>

#include "command_line.h"
#include "compiler.h"
#include "export_command.h"

int main(int argc, char** argv) {
    CLI::App app{"fgc export: a graph's surface as an OpenVDB level set and meshes"};
    app.name("fgc");
    app.set_version_flag("--version", std::string("fgc ") + fg::kCompilerVersion);
    app.require_subcommand(1);
    fg::fgc::Common common;
    app.add_option("--nodes", common.node_folders, "extra node library folder (repeatable)")->check(CLI::ExistingDirectory);
    std::string graph;
    fg::fgc::ExportOptions options;
    fg::fgc::add_export_command(app, graph, options);
    if (auto failed = fg::cli::parse(app, argc, argv)) return *failed;
    return fg::fgc::export_level_set(common, graph, options);
}
