#include "studio/studio_server.h"

#include <fmt/format.h>

#include "studio/studio_page.h"
#include "studio/studio_routes.h"

namespace fg::studio {

StudioServer::StudioServer(StudioSession& session, const ServerOptions& options) : options_(options) {
    server_.set_payload_max_length(options_.max_body_bytes);
    server_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (auto why = guard_->refuse(req.get_header_value("Host"), req.get_header_value("Origin"))) {
            res.status = 403;
            res.set_content(nlohmann::json{{"error", *why}}.dump(), "application/json");
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });
    add_api_routes(server_, session, options_.opened_graph);
    server_.Get(R"(/(?!api/).*)", [](const httplib::Request& req, httplib::Response& res) {
        auto file = page_file(req.path);
        if (!file) {
            res.status = 404;
            res.set_content("not found", "text/plain");
            return;
        }
        res.set_content(std::string(file->content), file->mime);
    });
    server_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
        std::string what = "internal error";
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& x) {
            what = x.what();
        } catch (...) {
        }
        res.status = 500;
        res.set_content(nlohmann::json{{"error", what}}.dump(), "application/json");
    });
    server_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
        if (!res.body.empty()) return;
        const char* why = res.status == 413 ? "the request body is larger than the studio accepts"
                          : res.status == 404 ? "no such API route" : "bad request";
        res.set_content(nlohmann::json{{"error", why}}.dump(), "application/json");
    });
}

StudioServer::~StudioServer() { stop(); }

bool StudioServer::bind(std::string& error) {
    port_ = options_.port == 0 ? server_.bind_to_any_port(options_.host) : (server_.bind_to_port(options_.host, options_.port) ? options_.port : -1);
    if (port_ <= 0) {
        error = fmt::format("cannot listen on {}:{} (in use, or not an address of this machine)", options_.host, options_.port);
        return false;
    }
    guard_ = std::make_unique<RequestGuard>(options_.host, port_);
    return true;
}

std::string StudioServer::url() const {
    bool ipv6 = options_.host.find(':') != std::string::npos;
    std::string host = ipv6 ? "[" + options_.host + "]" : options_.host;
    std::string query = options_.opened_graph.empty() ? "" : "?graph=" + options_.opened_graph;
    return fmt::format("http://{}:{}/{}", host, port_, query);
}

void StudioServer::listen() { server_.listen_after_bind(); }

void StudioServer::stop() {
    if (server_.is_running()) server_.stop();
}

}  // namespace fg::studio
