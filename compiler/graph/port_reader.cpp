#include "port_reader.h"

#include <fmt/format.h>

#include "common/json_fields.h"
#include "identifiers.h"
#include "literal.h"

namespace fg {

std::optional<PortDefinition> read_port_definition(const nlohmann::json& j, const std::string& ptr, bool is_input,
                                                   bool generic_allowed, bool doc_required, const ReportError& error) {
    JsonFieldReader r(error);
    if (!r.is_object(j, ptr)) return std::nullopt;
    r.unknown_keys(j, ptr, {"name", "type", "doc", "default", "min", "max", "knob", "effect"});
    PortDefinition p;
    r.required(j, "name", ptr, p.name);
    if (!p.name.empty() && !is_valid_identifier(p.name))
        error(fmt::format("port name \"{}\" is not a valid identifier (lower case, digits, '_') or is reserved", p.name),
              ptr + "/name");
    std::string type;
    r.required(j, "type", ptr, type);
    if (type == "T") {
        if (!generic_allowed) error("generic type T needs the node to list its \"generic\" types", ptr + "/type");
    } else if (auto t = parse_type(type)) {
        p.type.concrete = *t;
    } else if (!type.empty()) {
        error(fmt::format("unknown type \"{}\" (float, int, bool, vec2, vec3, vec4)", type), ptr + "/type");
    }
    if (doc_required) r.required(j, "doc", ptr, p.doc);
    else r.optional(j, "doc", ptr, p.doc);
    for (const char* bound : {"min", "max"})
        if (double x = 0.0; r.optional(j, bound, ptr, x)) (bound == std::string("min") ? p.min : p.max) = x;
    if (p.min && p.max && *p.min > *p.max) error("min is greater than max", ptr + "/min");
    if (j.contains("default")) {
        if (!is_input) {
            error("outputs have no default", ptr + "/default");
        } else if (j["default"].is_string()) {
            auto s = j["default"].get<std::string>();
            if (auto src = parse_implicit_source(s)) {
                p.implicit = *src;
                if (p.type.concrete != implicit_source_type(*src))
                    error(fmt::format("default \"{}\" is a {}, the port is {}", s, type_name(implicit_source_type(*src)),
                                      p.type.text()),
                          ptr + "/default");
            } else {
                error(fmt::format("default \"{}\": a string default is position, time, light, to_camera or normal", s),
                      ptr + "/default");
            }
        } else {
            Diagnostics local;
            LiteralSite site{ptr + "/default", {}};
            if (auto c = read_literal(j["default"], site, local)) {
                if (p.type.concrete) {
                    if (auto cc = coerce_literal(*c, *p.type.concrete, site, local)) {
                        if (check_range(*cc, p.min, p.max, site, local)) p.default_value = *cc;
                    }
                } else {
                    p.default_value = *c;  // generic: broadcast when the type is known
                }
            }
            for (const auto& d : local.items()) error(d.message, d.pointer);
        }
    }
    // iterations and bias: a fractal's; steps and rays: what a marched light term costs (0 turns it off).
    if (r.optional(j, "knob", ptr, p.knob, Choices{"iterations", "bias", "steps", "rays"})) {
        if (!is_input) error("only inputs can be knobs", ptr + "/knob");
        if (p.knob != "bias" && p.type.concrete != ValueType::Int) error(fmt::format("a {} knob is an int", p.knob), ptr);
        else if (p.knob == "bias" && p.type.concrete != ValueType::Float) error("a bias knob is a float", ptr);
    }
    if (std::string e; r.optional(j, "effect", ptr, e)) {
        if (auto eff = parse_effect(e)) p.effect = *eff;
        else error(fmt::format("unknown effect \"{}\"", e), ptr + "/effect");
    }
    return p;
}

}  // namespace fg
