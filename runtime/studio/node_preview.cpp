#include "studio/node_preview.h"

#include <set>

#include "compiler.h"
#include "graph/graph_text_writer.h"

namespace fg::studio {

namespace {
using nlohmann::ordered_json;

// The node ids a node's inputs read from ("bulb.trap", "bulb", {"node": "bulb"}); parameters and
// literals read none.
std::vector<std::string> upstream_ids(const ordered_json& node) {
    std::vector<std::string> out;
    auto inputs = node.find("inputs");
    if (inputs == node.end() || !inputs->is_object()) return out;
    for (const auto& [_, binding] : inputs->items()) {
        if (binding.is_string()) {
            const auto& s = binding.get_ref<const std::string&>();
            if (!s.empty() && s.front() != '$') out.push_back(s.substr(0, s.find('.')));
        } else if (binding.is_object() && binding.contains("node") && binding["node"].is_string()) {
            out.push_back(binding["node"].get<std::string>());
        }
    }
    return out;
}
}  // namespace

std::optional<ordered_json> distance_subgraph(const ordered_json& graph, const std::string& node_id, const std::string& port,
                                              std::string& error) {
    if (!graph.is_object() || !graph.contains("nodes") || !graph["nodes"].is_array()) {
        error = "the graph has no nodes";
        return std::nullopt;
    }
    std::map<std::string, const ordered_json*> by_id;
    for (const auto& n : graph["nodes"])
        if (n.is_object() && n.contains("id") && n["id"].is_string()) by_id[n["id"].get<std::string>()] = &n;
    if (!by_id.count(node_id)) {
        error = "no node '" + node_id + "'";
        return std::nullopt;
    }
    std::set<std::string> needed;
    std::vector<std::string> todo{node_id};
    while (!todo.empty()) {
        std::string id = todo.back();
        todo.pop_back();
        if (!by_id.count(id) || !needed.insert(id).second) continue;
        for (auto& up : upstream_ids(*by_id[id])) todo.push_back(up);
    }
    ordered_json sub = ordered_json::object();
    for (const char* key : {"format", "version", "name", "params", "scene"})
        if (graph.contains(key)) sub[key] = graph[key];
    // A node's thumbnail is lit by a uniform sky of the environment's colour: no image file is read.
    if (sub.contains("scene") && sub["scene"].is_object() && sub["scene"].contains("environment") &&
        sub["scene"]["environment"].is_object())
        sub["scene"]["environment"].erase("image");
    sub["nodes"] = ordered_json::array();
    for (const auto& n : graph["nodes"])
        if (n.is_object() && n.contains("id") && n["id"].is_string() && needed.count(n["id"].get<std::string>()))
            sub["nodes"].push_back(n);
    sub["outputs"] = {{"distance", node_id + "." + port}};
    return sub;
}

NodePreviews::NodePreviews(const vk::Context& ctx, const NodeLibrary& library, std::uint32_t size)
    : ctx_(ctx), library_(library), size_(size) {}

std::optional<std::vector<std::uint8_t>> NodePreviews::render(const std::string& graph_text, const std::string& node_id,
                                                              const std::string& port,
                                                              const std::map<std::string, Constant>& params,
                                                              std::string& error) {
    auto graph = ordered_json::parse(graph_text, nullptr, false);
    auto sub = distance_subgraph(graph, node_id, port, error);
    if (!sub) return std::nullopt;
    std::string text = format_graph_text(*sub);
    std::string key = content_hash(text);

    std::lock_guard lock(mutex_);
    auto it = std::find_if(kept_.begin(), kept_.end(), [&](const auto& k) { return k.first == key; });
    if (it == kept_.end()) {
        Diagnostics diag;
        ++compiles_;
        CompileOptions options;
        options.cache = &pass_cache_;
        auto result = compile_graph(text, library_, options, diag);
        std::optional<Pack> pack;
        if (result) pack = read_pack(pack_bytes(*result), diag);
        if (!pack) {
            error = diag.format();
            return std::nullopt;
        }
        kept_.emplace_front(key, prepare_scene(ctx_, std::move(*pack), 0, size_, false));
        if (kept_.size() > kKept) kept_.pop_back();
    } else {
        kept_.splice(kept_.begin(), kept_, it);
    }
    PreviewRequest request;
    request.params = params;
    RenderedFrame rendered;
    return render_scene(*kept_.front().second, request, 0, rendered).png;
}

std::uint64_t NodePreviews::compiles() const {
    std::lock_guard lock(mutex_);
    return compiles_;
}

}  // namespace fg::studio
