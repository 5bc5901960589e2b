#pragma once
// Errors are values that say where they came from: a node id, a JSON pointer into the graph, a
// byte offset into a pack. Every compiler stage appends to one Diagnostics list so a run reports
// all it found, not just the first problem.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fg {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string message;
    std::string node_id;                    // graph node the problem belongs to, if any
    std::string pointer;                    // JSON pointer into the graph, e.g. /nodes/3/inputs/power
    std::optional<std::uint64_t> byte;      // offset into a binary file, for pack errors
    std::string context;                    // extra lines shown under the message (generated GLSL...)
};

class Diagnostics {
public:
    void error(std::string message, std::string pointer = {}, std::string node_id = {});
    void warning(std::string message, std::string pointer = {}, std::string node_id = {});
    void note(std::string message, std::string pointer = {}, std::string node_id = {});
    void add(Diagnostic d) { items_.push_back(std::move(d)); }
    void append(const Diagnostics& other);

    bool has_errors() const;
    std::size_t error_count() const;
    const std::vector<Diagnostic>& items() const { return items_; }
    bool empty() const { return items_.empty(); }

    // One diagnostic per line (plus indented context), prefixed with `file`:
    //   graphs/x.json: error: /nodes/3/inputs/power (node 'bulb'): expected float, got string
    std::string format(const std::string& file = {}) const;

private:
    std::vector<Diagnostic> items_;
};

std::string format_diagnostic(const Diagnostic& d, const std::string& file = {});

}  // namespace fg
