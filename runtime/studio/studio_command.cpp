#include "studio/studio_command.h"

#include <csignal>
#include <filesystem>
#include <fmt/format.h>

#include "studio/studio_server.h"
#include "tool/command_outcome.h"

namespace fg::studio {

namespace {
StudioServer* running_server = nullptr;
void stop_on_signal(int) {
    if (running_server) running_server->stop();
}
}  // namespace

void add_studio_command(CLI::App& app, StudioCommand& c) {
    c.command = app.add_subcommand("studio", "edit graphs in the browser with a live preview from this renderer");
    c.command->add_option("target", c.target, "a graph (.json) to open, or the folder to work in (default: here)")
        ->check(CLI::ExistingPath);
    c.command->add_option("--port", c.port, "TCP port (0: any free one)")->check(CLI::Range(0, 65535))->capture_default_str();
    c.command->add_option("--host", c.host, "address to listen on; other than loopback only on purpose")->capture_default_str();
    c.command->add_option("--size", c.size, "preview size per eye, in pixels")->check(CLI::Range(16, 2048))->capture_default_str();
    c.command->add_option("--fgc", c.fgc, "the fgc that calibrates (default: beside fgplay, or on PATH)");
    c.command->add_flag("--validation", c.validation, "Vulkan validation layer on");
    c.command->add_option("--device", c.device, "Vulkan device: index or name substring");
}

int StudioCommand::run() {
    namespace fs = std::filesystem;
    SessionOptions session_options;
    ServerOptions server_options;
    fs::path path(target);
    if (fs::is_regular_file(path)) {
        session_options.folder = fs::absolute(path).parent_path().string();
        server_options.opened_graph = path.filename().string();
    } else {
        session_options.folder = target;
    }
    session_options.eye_size = size;
    session_options.fgc = fgc;
    server_options.host = host;
    server_options.port = port;
    return fgplay::run_reporting_errors([&] {
        vk::Context ctx(fgplay::render_context_options(validation, device));
        StudioSession session(ctx, session_options);
        StudioServer server(session, server_options);
        std::string error;
        if (!server.bind(error)) {
            fmt::print(stderr, "fgplay studio: {}\n", error);
            return 1;
        }
        running_server = &server;
        std::signal(SIGINT, stop_on_signal);
        std::signal(SIGTERM, stop_on_signal);
        fmt::print("Fractograph Studio on {} ({}), folder {}\n{}\n", ctx.device_name(), size, session.folder().root().string(),
                   server.url());
        std::fflush(stdout);
        server.listen();
        running_server = nullptr;
        return 0;
    });
}

}  // namespace fg::studio
