#pragma once
// The node library: every node definition the compiler knows, loaded from the files embedded in
// the binary (nodes/ at build time) and optionally from extra folders of the user's own.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/diagnostics.h"
#include "common/embedded_file.h"
#include "node_definition.h"

namespace fg {

class NodeLibrary {
public:
    // The library built into this binary. Loaded once; a broken built-in definition is a build bug
    // and aborts with the diagnostics.
    static const NodeLibrary& builtin();

    // Build a library from definition/body file pairs (path "ns/name.json" + "ns/name.glsl").
    // Files named prelude.glsl hold helpers shared by every body.
    static NodeLibrary from_files(std::span<const EmbeddedFile> files, Diagnostics& diag);

    // Add the definitions found under a folder on disk (user node libraries).
    void load_folder(const std::string& folder, Diagnostics& diag);

    const NodeDefinition* find(const std::string& type) const;
    std::vector<const NodeDefinition*> all() const;   // sorted by type
    const std::string& prelude() const { return prelude_; }
    // nodes/double_math.glsl: sin, pow, ... in double, for scenes compiled with precision "double".
    const std::string& double_math() const { return double_math_; }
    // nodes/jacobian.glsl: helpers of formulas that carry a running Jacobian.
    const std::string& jacobian() const { return jacobian_; }
    // Types whose name is close to `type`, for "did you mean" hints.
    std::vector<std::string> similar(const std::string& type) const;

private:
    void add_definition(const std::string& json_path, std::string_view json_text, std::string glsl_path,
                        std::string glsl_text, Diagnostics& diag);
    std::map<std::string, std::unique_ptr<NodeDefinition>> defs_;
    std::string prelude_;
    std::string double_math_;
    std::string jacobian_;
};

// Parse one definition; reports problems against json_path.
std::unique_ptr<NodeDefinition> parse_node_definition(const std::string& json_path, std::string_view json_text,
                                                      Diagnostics& diag);

}  // namespace fg
