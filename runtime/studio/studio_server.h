#pragma once
// The studio's HTTP server: every request passes the guard (Host, Origin), bodies are bounded,
// the API answers under /api/ and the page, built into the binary, is served for everything else.
#include <memory>
#include <string>

#include <httplib.h>

#include "studio/request_guard.h"
#include "studio/studio_session.h"

namespace fg::studio {

struct ServerOptions {
    std::string host = "127.0.0.1";
    int port = 8765;                          // 0: any free port
    std::size_t max_body_bytes = 4u << 20;    // a graph is a few kB; 4 MiB is generous
    std::string opened_graph;                 // relative to the folder; the page opens it first
};

class StudioServer {
public:
    StudioServer(StudioSession& session, const ServerOptions& options);
    ~StudioServer();

    // Binds; false with `error` when the address is taken or not ours.
    bool bind(std::string& error);
    int port() const { return port_; }
    std::string url() const;
    // Serves until stop() (from another thread or a signal).
    void listen();
    void stop();

private:
    httplib::Server server_;
    ServerOptions options_;
    int port_ = 0;
    std::unique_ptr<RequestGuard> guard_;
};

}  // namespace fg::studio
