#pragma once
// The `fgplay studio` subcommand: a node editor in the browser with a live preview from this
// renderer. It prints the URL and serves until interrupted.
#include <string>

#include <CLI/CLI.hpp>

namespace fg::studio {

struct StudioCommand {
    std::string target = ".";   // a graph (its folder is the studio's) or a folder
    std::string host = "127.0.0.1";
    int port = 8765;
    std::uint32_t size = 256;
    std::string fgc, device;
    bool validation = false;
    CLI::App* command = nullptr;

    bool chosen() const { return command && command->parsed(); }
    int run();
};

void add_studio_command(CLI::App& app, StudioCommand& c);

}  // namespace fg::studio
