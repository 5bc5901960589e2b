#pragma once
// `fgc export`'s command line, shared by fgc (which only names the command and hands the whole
// command line to fgc-export) and fgc-export (which parses it: the same options, the same help).
#include <string>

#include <CLI/CLI.hpp>

#include "fgc_commands.h"

namespace fg::fgc {

// One line for fgc's help: what the command does.
inline constexpr const char* kExportSummary =
    "sample the graph's surface into an OpenVDB level set (.vdb) and meshes of it (PLY, OBJ, STL), or merge the "
    "shards of a job array (docs/export.md)";

// fgc's `export`: named, its arguments left for fgc-export.
CLI::App* add_export_placeholder(CLI::App& app);
// Runs fgc-export (beside this executable, else on PATH) with this process's arguments, argv[0]
// included; returns only when it cannot be started (exit code 127, with the reason on stderr).
int run_export_program(char** argv);

// fgc-export's `export`, with every option.
CLI::App* add_export_command(CLI::App& app, std::string& graph, ExportOptions& options);

}  // namespace fg::fgc
