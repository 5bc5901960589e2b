#include "graph_text_writer.h"

namespace fg {

namespace {

// One line of JSON with a space after ',' and ':' (nlohmann's compact form has none).
std::string compact(const nlohmann::ordered_json& j) {
    if (j.is_object()) {
        std::string s = "{";
        bool first = true;
        for (auto it = j.begin(); it != j.end(); ++it) {
            s += (first ? "" : ", ") + nlohmann::ordered_json(it.key()).dump() + ": " + compact(it.value());
            first = false;
        }
        return s + "}";
    }
    if (j.is_array()) {
        std::string s = "[";
        for (std::size_t i = 0; i < j.size(); ++i) s += (i ? ", " : "") + compact(j[i]);
        return s + "]";
    }
    return j.dump();
}

bool has_containers(const nlohmann::ordered_json& j) {
    for (const auto& v : j)
        if (v.is_object() || v.is_array()) return true;
    return false;
}

// A node on one line, except a formula's body: a line per group and per stage, so a diff of an
// edited stage is one line.
std::string node_text(const nlohmann::ordered_json& node) {
    if (!node.is_object() || !node.contains("formula") || !node["formula"].is_object()) return compact(node);
    std::string s = "{";
    for (auto it = node.begin(); it != node.end(); ++it)
        if (it.key() != "formula") s += nlohmann::ordered_json(it.key()).dump() + ": " + compact(it.value()) + ", ";
    s += "\"formula\": {";
    const auto& formula = node["formula"];
    std::size_t i = 0;
    for (auto it = formula.begin(); it != formula.end(); ++it, ++i) {
        s += "\n      " + nlohmann::ordered_json(it.key()).dump() + ": ";
        const auto& groups = it.value();
        if (it.key() == "groups" && groups.is_array()) {
            s += "[";
            for (std::size_t g = 0; g < groups.size(); ++g) {
                const auto& group = groups[g];
                if (!group.is_object() || !group.contains("nodes") || !group["nodes"].is_array()) {
                    s += "\n        " + compact(group);
                } else {
                    s += "\n        {";
                    for (auto f = group.begin(); f != group.end(); ++f)
                        if (f.key() != "nodes") s += nlohmann::ordered_json(f.key()).dump() + ": " + compact(f.value()) + ", ";
                    s += "\"nodes\": [";
                    const auto& stages = group["nodes"];
                    for (std::size_t k = 0; k < stages.size(); ++k)
                        s += "\n          " + compact(stages[k]) + (k + 1 < stages.size() ? "," : "");
                    s += "]}";
                }
                s += g + 1 < groups.size() ? "," : "";
            }
            s += "]";
        } else {
            s += compact(groups);
        }
        s += i + 1 < formula.size() ? "," : "";
    }
    return s + "}}";
}

}  // namespace

std::string format_graph_text(const nlohmann::ordered_json& graph) {
    if (!graph.is_object()) return compact(graph) + "\n";
    std::string s = "{\n";
    bool first = true;
    for (auto it = graph.begin(); it != graph.end(); ++it) {
        s += first ? "" : ",\n";
        first = false;
        s += "  " + nlohmann::ordered_json(it.key()).dump() + ": ";
        const auto& v = it.value();
        if ((v.is_object() || v.is_array()) && v.size() > 1 && (has_containers(v) || compact(v).size() > 100)) {
            bool obj = v.is_object();
            s += obj ? "{\n" : "[\n";
            std::size_t i = 0;
            for (auto m = v.begin(); m != v.end(); ++m, ++i) {
                s += "    ";
                if (obj) s += nlohmann::ordered_json(m.key()).dump() + ": ";
                s += (it.key() == "nodes" ? node_text(*m) : compact(*m)) + (i + 1 < v.size() ? ",\n" : "\n");
            }
            s += obj ? "  }" : "  ]";
        } else {
            s += compact(v);
        }
    }
    return s + "\n}\n";
}

}  // namespace fg
