#pragma once
// The `fgplay xr` subcommand: its options and how they become XrPlayOptions.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "xr/xr_player.h"

namespace fg::xr {

struct XrCommand {
    XrPlayOptions options;
    std::string size, stereo = "per-eye";
    std::vector<std::string> knobs;
    CLI::App* command = nullptr;

    bool chosen() const { return command && command->parsed(); }
    int run();
};

void add_xr_command(CLI::App& app, XrCommand& c);

}  // namespace fg::xr
