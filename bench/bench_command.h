#pragma once
// The `fgplay bench` subcommand: its options and how they become BenchOptions. Registered by the
// fgplay executable beside the runtime's own commands, so the runtime never depends on the benchmark.
#include <CLI/CLI.hpp>

#include "bench_runner.h"

namespace fg::bench {

struct BenchCommand {
    BenchOptions options;
    bool no_plots = false;
    CLI::App* command = nullptr;

    bool chosen() const { return command && command->parsed(); }
    int run();
};

void add_bench_command(CLI::App& app, BenchCommand& c);

}  // namespace fg::bench
