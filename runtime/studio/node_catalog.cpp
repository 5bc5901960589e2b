#include "studio/node_catalog.h"

namespace fg::studio {

namespace {
nlohmann::json port_json(const PortDefinition& p) {
    nlohmann::json j{{"name", p.name}, {"type", p.type.text()}, {"doc", p.doc}};
    if (p.default_value) {
        const Constant& c = *p.default_value;
        if (component_count(c.type) == 1) {
            j["default"] = c.v[0];
        } else {
            j["default"] = std::vector<double>(c.v.begin(), c.v.begin() + component_count(c.type));
        }
    }
    if (p.implicit != ImplicitSource::None) j["implicit"] = std::string(implicit_source_name(p.implicit));
    if (p.min) j["min"] = *p.min;
    if (p.max) j["max"] = *p.max;
    if (!p.knob.empty()) j["knob"] = p.knob;
    return j;
}
}  // namespace

nlohmann::json node_catalog_json(const NodeLibrary& library) {
    nlohmann::json nodes = nlohmann::json::array();
    for (const NodeDefinition* def : library.all()) {
        nlohmann::json inputs = nlohmann::json::array(), outputs = nlohmann::json::array(), generic = nlohmann::json::array();
        for (const auto& p : def->inputs) inputs.push_back(port_json(p));
        for (const auto& p : def->outputs) outputs.push_back(port_json(p));
        for (ValueType t : def->generic) generic.push_back(std::string(type_name(t)));
        nodes.push_back({{"type", def->type},
                         {"category", def->namespace_name()},
                         {"summary", def->summary},
                         {"doc", def->doc},
                         {"shade_only", def->context == NodeContext::Shade},
                         {"inputs", inputs},
                         {"outputs", outputs},
                         {"generic", generic},
                         // Stages live in a formula's body, not on the canvas; a new node starts from
                         // its example (a formula node, from a whole body).
                         {"stage", def->is_stage()},
                         // What the palette offers inside an open body: stages, and maths nodes
                         // with a tangent rule (a body carrying them carries the Jacobian).
                         {"in_body", def->fits_in_formula_body()},
                         {"example", def->example.is_object() ? def->example : nlohmann::json::object()}});
    }
    return nodes;
}

}  // namespace fg::studio
