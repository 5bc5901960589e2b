#pragma once
// Where each line of generated GLSL came from: a graph node (and its JSON pointer), a node
// library body, or a runtime pass template. glslang reports errors by generated line; this maps
// them back to what the author wrote.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fg {

struct SourceOrigin {
    enum class Kind { Template, Library, Node, Generated } kind = Kind::Generated;
    std::string file;       // template or library file (Template, Library)
    std::string node_id;    // Node: the graph node
    std::string pointer;    // Node: JSON pointer (the node, or its custom code)
    int line = 0;           // line within file or custom code (1-based), 0 if not applicable
};

class SourceMap {
public:
    // Record that generated line `generated` (1-based) came from `origin`.
    void add(int generated, SourceOrigin origin);
    std::optional<SourceOrigin> lookup(int generated) const;
    std::size_t size() const { return lines_.size(); }
    nlohmann::json to_json() const;
    static SourceMap from_json(const nlohmann::json& j);

private:
    std::vector<SourceOrigin> lines_;  // index = generated line - 1
};

}  // namespace fg
