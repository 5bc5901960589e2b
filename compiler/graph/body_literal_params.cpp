#include "body_literal_params.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fg {

namespace {

using json = nlohmann::ordered_json;

// The literal's value as the port takes it: a number for a float port, n numbers (or one, for all
// n) for a vecn.
bool fits(const json& literal, const PortDefinition& port) {
    if (!port.type.concrete || !port.knob.empty()) return false;
    const ValueType t = *port.type.concrete;
    const int n = component_count(t);
    if (t == ValueType::Int || t == ValueType::Bool) return false;
    std::vector<double> xs;
    if (literal.is_number()) xs.assign(static_cast<std::size_t>(n), literal.get<double>());
    if (n > 1 && literal.is_array() && static_cast<int>(literal.size()) == n)
        for (const auto& x : literal)
            if (x.is_number()) xs.push_back(x.get<double>());
    if (static_cast<int>(xs.size()) != n) return false;
    for (double x : xs)
        if ((port.min && x < *port.min) || (port.max && x > *port.max)) return false;
    return true;
}

}  // namespace

std::string with_body_literals_as_params(const std::string& graph_text, const NodeLibrary& library) {
    json graph = json::parse(graph_text, nullptr, false);
    if (!graph.is_object() || !graph.contains("nodes") || !graph["nodes"].is_array()) return graph_text;
    if (graph.contains("params") && !graph["params"].is_object()) return graph_text;
    json& params = graph["params"];
    if (params.is_null()) params = json::object();
    int next = 0;
    bool changed = false;
    for (auto& node : graph["nodes"]) {
        if (!node.is_object() || !node.contains("formula") || !node["formula"].is_object()) continue;
        auto& groups = node["formula"]["groups"];
        if (!groups.is_array()) continue;
        for (auto& group : groups) {
            if (!group.is_object() || !group.contains("nodes") || !group["nodes"].is_array()) continue;
            for (auto& stage : group["nodes"]) {
                if (!stage.is_object() || !stage.contains("inputs") || !stage["inputs"].is_object() || !stage["type"].is_string()) continue;
                const NodeDefinition* def = library.find(stage["type"].get<std::string>());
                if (!def) continue;
                for (auto& [name, value] : stage["inputs"].items()) {
                    const PortDefinition* port = def->find_input(name);
                    if (!port || !fits(value, *port)) continue;
                    std::string param;
                    do param = fmt::format("fgbody_{}", next++);
                    while (params.contains(param));
                    params[param] = {{"type", std::string(type_name(*port->type.concrete))}, {"default", value}};
                    value = "$" + param;
                    changed = true;
                }
            }
        }
    }
    return changed ? graph.dump() : graph_text;
}

}  // namespace fg
