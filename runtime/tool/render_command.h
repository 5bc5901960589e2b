#pragma once
// The `fgplay render` subcommand: its options and how they become RenderOptions.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fgplay_render.h"

namespace fg::fgplay {

struct RenderCommand {
    RenderOptions options;
    std::string size = "512x512", stereo = "per-eye", camera, frames = "1", projection = "perspective", format = "png",
                compression = "zip";
    std::vector<std::string> knobs;
    bool naive = false;
    CLI::App* command = nullptr;

    bool chosen() const { return command && command->parsed(); }
    int run();
};

void add_render_command(CLI::App& app, RenderCommand& c);

}  // namespace fg::fgplay
