#include "studio/diagnostics_json.h"

namespace fg::studio {

nlohmann::json diagnostics_json(const Diagnostics& diag) {
    nlohmann::json out = nlohmann::json::array();
    for (const Diagnostic& d : diag.items()) {
        const char* severity = d.severity == Severity::Error ? "error" : d.severity == Severity::Warning ? "warning" : "note";
        out.push_back({{"severity", severity},
                       {"message", d.message},
                       {"pointer", d.pointer},
                       {"node", d.node_id},
                       {"context", d.context},
                       {"text", format_diagnostic(d)}});
    }
    return out;
}

}  // namespace fg::studio
