#pragma once
// The `fgplay view` subcommand: its options and how they become ViewOptions.
#include <string>

#include <CLI/CLI.hpp>

#include "desktop/desktop_viewer.h"

namespace fg::desktop {

struct ViewCommand {
    ViewOptions options;
    std::string size = "256x256", stereo = "per-eye";
    CLI::App* command = nullptr;

    bool chosen() const { return command && command->parsed(); }
    int run();
};

void add_view_command(CLI::App& app, ViewCommand& c);

}  // namespace fg::desktop
