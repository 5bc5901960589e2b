#include "studio/studio_routes.h"

#include <fmt/format.h>

#include "compiler.h"
#include "studio/diagnostics_json.h"
#include "studio/graph_document.h"
#include "studio/node_catalog.h"

namespace fg::studio {

namespace {
// Ordered: a graph goes back to the page with its keys in the order of its file.
using json = nlohmann::ordered_json;
using nlohmann::ordered_json;

void reply(httplib::Response& res, int status, const json& body) {
    res.status = status;
    res.set_content(body.dump(), "application/json");
}

void refuse(httplib::Response& res, int status, const std::string& message) { reply(res, status, {{"error", message}}); }

// The request's JSON object, or a 400 that says what is wrong with it.
std::optional<ordered_json> body_object(const httplib::Request& req, httplib::Response& res) {
    ordered_json body;
    try {
        body = ordered_json::parse(req.body);
    } catch (const json::parse_error& e) {
        refuse(res, 400, fmt::format("the request body is not JSON: {}", e.what()));
        return std::nullopt;
    }
    if (!body.is_object()) {
        refuse(res, 400, "the request body must be a JSON object");
        return std::nullopt;
    }
    return body;
}

// A field the request must carry, of the given kind.
const ordered_json* field(const ordered_json& body, const char* name, json::value_t kind, httplib::Response& res) {
    auto it = body.find(name);
    bool ok = it != body.end() && (it->type() == kind || (kind == json::value_t::number_float && it->is_number()));
    if (!ok) {
        refuse(res, 400, fmt::format("'{}' is required ({})", name, json(kind).type_name()));
        return nullptr;
    }
    return &*it;
}

std::optional<std::string> graph_text(const ordered_json& body, httplib::Response& res) {
    const auto* graph = field(body, "graph", json::value_t::object, res);
    if (!graph) return std::nullopt;
    return graph->dump();
}

// {"power": 7.5, "offset": [0, 1, 0], "on": true} -> constants; the pack knows each one's type.
std::map<std::string, Constant> param_values(const ordered_json& body) {
    std::map<std::string, Constant> out;
    auto it = body.find("params");
    if (it == body.end() || !it->is_object()) return out;
    for (const auto& [name, value] : it->items()) {
        Constant c;
        if (value.is_number() || value.is_boolean()) {
            c.v[0] = value.is_boolean() ? (value.get<bool>() ? 1.0 : 0.0) : value.get<double>();
        } else if (value.is_array() && value.size() <= 4) {
            for (std::size_t i = 0; i < value.size(); ++i)
                if (value[i].is_number()) c.v[i] = value[i].get<double>();
        } else {
            continue;
        }
        out[name] = c;
    }
    return out;
}

std::optional<glm::dvec3> vec3_at(const ordered_json& j, const char* key) {
    auto it = j.find(key);
    if (it == j.end() || !it->is_array() || it->size() != 3) return std::nullopt;
    for (const auto& x : *it)
        if (!x.is_number()) return std::nullopt;
    return glm::dvec3((*it)[0].get<double>(), (*it)[1].get<double>(), (*it)[2].get<double>());
}

json state_json(StudioSession& s, const EditOutcome& o) {
    return {{"revision", o.revision},          {"ok", o.ok},
            {"diagnostics", o.diagnostics},    {"compile_ms", o.compile_ms},
            {"pipelines_ms", o.pipelines_ms},  {"glslang_ms", o.glslang_ms},
            {"optimize_ms", o.optimize_ms},    {"passes_compiled", o.passes_compiled},
            {"compiles", s.compiles()},
            {"submitted", s.edits().submitted()}, {"skipped", s.edits().skipped()},
            {"busy", s.edits().busy()},        {"frames", s.preview().frames()},
            {"node_preview_compiles", s.node_previews().compiles()}};
}

void send_png(httplib::Response& res, std::vector<std::uint8_t> png) {
    res.set_content(std::string(png.begin(), png.end()), "image/png");
}

void add_file_routes(httplib::Server& server, StudioSession& s, const std::string& opened_graph) {
    server.Get("/api/nodes", [&s](const httplib::Request&, httplib::Response& res) {
        reply(res, 200, {{"nodes", node_catalog_json(s.library())}});
    });
    server.Get("/api/graphs", [&s, opened_graph](const httplib::Request&, httplib::Response& res) {
        reply(res, 200, {{"folder", s.folder().root().string()}, {"graphs", s.folder().list_graphs()}, {"opened", opened_graph}});
    });
    server.Get("/api/graph", [&s](const httplib::Request& req, httplib::Response& res) {
        std::string error;
        auto text = s.folder().read(req.get_param_value("path"), error);
        if (!text) return refuse(res, error.find("no such") != std::string::npos ? 404 : 400, error);
        auto graph = ordered_json::parse(*text, nullptr, false);
        if (graph.is_discarded()) return refuse(res, 422, req.get_param_value("path") + ": not valid JSON");
        reply(res, 200, {{"path", req.get_param_value("path")}, {"graph", graph}});
    });
    server.Post("/api/save", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        if (!body) return;
        const auto* path = field(*body, "path", json::value_t::string, res);
        const auto* graph = path ? field(*body, "graph", json::value_t::object, res) : nullptr;
        if (!graph) return;
        // The graph it was opened from keeps its number spelling (8.0 stays 8.0).
        std::string error, based_on = body->value("based_on", path->get<std::string>());
        std::optional<ordered_json> original;
        if (s.folder().resolve(based_on, error))
            if (auto text = s.folder().read(based_on, error)) original = ordered_json::parse(*text, nullptr, false);
        std::string text = canonical_graph_text(*graph, original && !original->is_discarded() ? &*original : nullptr);
        error.clear();
        if (!s.folder().write(path->get<std::string>(), text, error)) return refuse(res, 400, error);
        Diagnostics diag;
        load_and_lower(text, s.library(), diag);
        reply(res, 200, {{"path", *path}, {"bytes", text.size()}, {"diagnostics", diagnostics_json(diag)}});
    });
    server.Post("/api/export", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        if (!body) return;
        const auto* path = field(*body, "path", json::value_t::string, res);
        auto text = path ? graph_text(*body, res) : std::nullopt;
        if (!text) return;
        std::string error;
        auto target = s.folder().resolve(path->get<std::string>(), error);
        if (!target) return refuse(res, 400, error);
        if (target->extension() != ".fgpack") return refuse(res, 400, "a shader pack's name ends in .fgpack");
        Diagnostics diag;
        CompileOptions options;
        options.cache = &s.pass_cache();   // passes the preview compiled optimised are not compiled again
        options.folder = s.folder().root().string();
        options.folder_confined = true;
        auto result = compile_graph(*text, s.library(), options, diag);
        if (!result) return reply(res, 422, {{"error", "the graph does not compile"}, {"diagnostics", diagnostics_json(diag)}});
        auto bytes = pack_bytes(*result);
        std::ofstream(*target, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                       static_cast<std::streamsize>(bytes.size()));
        reply(res, 200, {{"path", *path}, {"bytes", bytes.size()}});
    });
}

void add_compile_routes(httplib::Server& server, StudioSession& s) {
    server.Post("/api/validate", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        auto text = body ? graph_text(*body, res) : std::nullopt;
        if (!text) return;
        Diagnostics diag;
        bool ok = load_and_lower(*text, s.library(), diag).has_value();
        reply(res, 200, {{"ok", ok}, {"diagnostics", diagnostics_json(diag)}});
    });
    server.Post("/api/edit", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        auto text = body ? graph_text(*body, res) : std::nullopt;
        if (!text) return;
        reply(res, 202, {{"revision", s.edits().submit(std::move(*text))}});
    });
    server.Get("/api/state", [&s](const httplib::Request& req, httplib::Response& res) {
        std::uint64_t after = 0;
        long wait_ms = 0;
        try {
            if (req.has_param("after")) after = std::stoull(req.get_param_value("after"));
            if (req.has_param("wait_ms")) wait_ms = std::clamp(std::stol(req.get_param_value("wait_ms")), 0L, 10000L);
        } catch (const std::exception&) {
            return refuse(res, 400, "after and wait_ms are whole numbers");
        }
        reply(res, 200, state_json(s, s.edits().wait_for(after, std::chrono::milliseconds(wait_ms))));
    });
}

void add_preview_routes(httplib::Server& server, StudioSession& s) {
    server.Post("/api/frame", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        if (!body) return;
        PreviewRequest request;
        if (auto camera = body->find("camera"); camera != body->end() && camera->is_object()) {
            request.position = vec3_at(*camera, "position");
            request.target = vec3_at(*camera, "target");
        }
        request.side_by_side = body->value("stereo", "mono") == "side-by-side";
        request.params = param_values(*body);
        if (auto width = body->find("display_width"); width != body->end() && width->is_number() && width->get<double>() > 0.0)
            request.display_width = std::min(width->get<double>(), 16384.0);
        auto frame = s.preview().render(request);
        if (!frame) return refuse(res, 409, "no graph has compiled yet");
        res.set_header("X-Fg-Gpu-Ms", fmt::format("{:.3f}", frame->gpu_ms));
        res.set_header("X-Fg-Cpu-Ms", fmt::format("{:.3f}", frame->cpu_ms));
        res.set_header("X-Fg-Evaluations-Per-Pixel", fmt::format("{:.2f}", frame->evaluations_per_pixel));
        res.set_header("X-Fg-Revision", std::to_string(frame->revision));
        res.set_header("X-Fg-Samples", std::to_string(frame->samples));
        res.set_header("X-Fg-Compiles", std::to_string(s.compiles()));
        send_png(res, std::move(frame->png));
    });
    server.Post("/api/probe", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        if (!body) return;
        const auto* x = field(*body, "x", json::value_t::number_float, res);
        const auto* y = x ? field(*body, "y", json::value_t::number_float, res) : nullptr;
        if (!y || x->get<double>() < 0 || y->get<double>() < 0) return;
        auto hit = s.preview().probe(x->get<std::uint32_t>(), y->get<std::uint32_t>());
        if (!hit) return refuse(res, 409, "no frame to probe at that pixel");
        reply(res, 200, {{"hit", hit->hit},
                         {"point", {hit->point.x, hit->point.y, hit->point.z}},
                         {"depth", hit->depth},
                         {"distance", hit->distance}});
    });
    server.Post("/api/node-preview", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        auto text = body ? graph_text(*body, res) : std::nullopt;
        const auto* node = text ? field(*body, "node", json::value_t::string, res) : nullptr;
        if (!node) return;
        std::string error;
        auto png = s.node_previews().render(*text, node->get<std::string>(), body->value("port", "distance"),
                                            param_values(*body), error);
        if (!png) return refuse(res, 422, error);
        send_png(res, std::move(*png));
    });
    server.Post("/api/calibrate", [&s](const httplib::Request& req, httplib::Response& res) {
        auto body = body_object(req, res);
        auto text = body ? graph_text(*body, res) : std::nullopt;
        if (!text) return;
        int samples = std::clamp(body->value("samples", 2000), 1, 100000);
        std::string error;
        if (!s.calibration().start(*text, samples, error)) return refuse(res, 409, error);
        reply(res, 202, s.calibration().status());
    });
    server.Get("/api/calibrate", [&s](const httplib::Request&, httplib::Response& res) {
        reply(res, 200, s.calibration().status());
    });
}
}  // namespace

void add_api_routes(httplib::Server& server, StudioSession& session, const std::string& opened_graph) {
    add_file_routes(server, session, opened_graph);
    add_compile_routes(server, session);
    add_preview_routes(server, session);
}

}  // namespace fg::studio
