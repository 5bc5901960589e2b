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
                s += compact(*m) + (i + 1 < v.size() ? ",\n" : "\n");
            }
            s += obj ? "  }" : "  ]";
        } else {
            s += compact(v);
        }
    }
    return s + "\n}\n";
}

}  // namespace fg
