#include "studio/graph_document.h"

#include "graph/graph_text_writer.h"

namespace fg::studio {

namespace {
using nlohmann::ordered_json;

void keep_number_style(ordered_json& edited, const ordered_json& original) {
    if (edited.is_number_integer() && original.is_number_float()) {
        if (static_cast<double>(edited.get<std::int64_t>()) == original.get<double>()) edited = original;
        return;
    }
    if (edited.is_object() && original.is_object()) {
        for (auto it = edited.begin(); it != edited.end(); ++it)
            if (auto o = original.find(it.key()); o != original.end()) keep_number_style(it.value(), *o);
    } else if (edited.is_array() && original.is_array()) {
        for (std::size_t i = 0; i < edited.size() && i < original.size(); ++i) keep_number_style(edited[i], original[i]);
    }
}
}  // namespace

std::string canonical_graph_text(ordered_json edited, const ordered_json* original) {
    if (original) keep_number_style(edited, *original);
    return format_graph_text(edited);
}

}  // namespace fg::studio
