#include "source_map.h"

namespace fg {

void SourceMap::add(int generated, SourceOrigin origin) {
    if (generated < 1) return;
    if (lines_.size() < static_cast<std::size_t>(generated)) lines_.resize(static_cast<std::size_t>(generated));
    lines_[static_cast<std::size_t>(generated - 1)] = std::move(origin);
}

std::optional<SourceOrigin> SourceMap::lookup(int generated) const {
    if (generated < 1 || static_cast<std::size_t>(generated) > lines_.size()) return std::nullopt;
    return lines_[static_cast<std::size_t>(generated - 1)];
}

namespace {
const char* kind_name(SourceOrigin::Kind k) {
    switch (k) {
        case SourceOrigin::Kind::Template: return "template";
        case SourceOrigin::Kind::Library: return "library";
        case SourceOrigin::Kind::Node: return "node";
        case SourceOrigin::Kind::Generated: return "generated";
    }
    return "generated";
}
}  // namespace

// Runs of lines with the same origin are stored once: [first line, count, kind, file, node, pointer, line].
nlohmann::json SourceMap::to_json() const {
    nlohmann::json runs = nlohmann::json::array();
    std::size_t i = 0;
    while (i < lines_.size()) {
        const auto& o = lines_[i];
        std::size_t j = i + 1;
        while (j < lines_.size() && lines_[j].kind == o.kind && lines_[j].file == o.file &&
               lines_[j].node_id == o.node_id && lines_[j].pointer == o.pointer &&
               (o.line == 0 ? lines_[j].line == 0 : lines_[j].line == o.line + static_cast<int>(j - i)))
            ++j;
        runs.push_back({i + 1, j - i, kind_name(o.kind), o.file, o.node_id, o.pointer, o.line});
        i = j;
    }
    return runs;
}

SourceMap SourceMap::from_json(const nlohmann::json& j) {
    SourceMap m;
    if (!j.is_array()) return m;
    for (const auto& r : j) {
        if (!r.is_array() || r.size() != 7) continue;
        try {
            int first = r[0].get<int>(), count = r[1].get<int>();
            if (first < 1 || count < 1 || count > 1000000) continue;
            SourceOrigin o;
            std::string kind = r[2].get<std::string>();
            o.kind = kind == "template"  ? SourceOrigin::Kind::Template
                     : kind == "library" ? SourceOrigin::Kind::Library
                     : kind == "node"    ? SourceOrigin::Kind::Node
                                         : SourceOrigin::Kind::Generated;
            o.file = r[3].get<std::string>();
            o.node_id = r[4].get<std::string>();
            o.pointer = r[5].get<std::string>();
            int line = r[6].get<int>();
            for (int k = 0; k < count; ++k) {
                o.line = line == 0 ? 0 : line + k;
                m.add(first + k, o);
            }
        } catch (const nlohmann::json::exception&) {
            continue;
        }
    }
    return m;
}

}  // namespace fg
