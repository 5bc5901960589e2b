#include "manifest.h"

#include <fmt/format.h>
#include <set>

#include "common/json_fields.h"
#include "common/spec_constants.h"

namespace fg {

const ManifestPass* PackManifest::find_pass(const std::string& n) const {
    for (const auto& p : passes)
        if (p.name == n) return &p;
    return nullptr;
}
const ManifestSpecConstant* PackManifest::find_spec(const std::string& n) const {
    for (const auto& s : spec_constants)
        if (s.name == n) return &s;
    return nullptr;
}
const ManifestSpecConstant* PackManifest::find_spec(std::uint32_t id) const {
    for (const auto& s : spec_constants)
        if (s.id == id) return &s;
    return nullptr;
}
const ManifestParam* PackManifest::find_param(const std::string& n) const {
    for (const auto& p : params)
        if (p.name == n) return &p;
    return nullptr;
}

namespace {

using nlohmann::json;

json constant_json(const Constant& c) {
    json a = json::array();
    for (int i = 0; i < component_count(c.type); ++i) a.push_back(c.v[static_cast<std::size_t>(i)]);
    return a;
}

// Problems are reported as "manifest: ..." at "/manifest<pointer>".
struct ManifestReader : JsonFieldReader {
    explicit ManifestReader(Diagnostics& diag)
        : JsonFieldReader([&diag](const std::string& message, const std::string& pointer) {
              diag.error("manifest: " + message, "/manifest" + pointer);
          }) {}

    bool ok() const { return errors() == 0; }
    // What parameters and specialization constants both declare.
    template <class Declared>
    void declaration(const json& j, const std::string& ptr, Declared& d) {
        required(j, "name", ptr, d.name);
        required(j, "type", ptr, d.type);
        d.min = bound(j, "min", ptr);
        d.max = bound(j, "max", ptr);
        optional(j, "doc", ptr, d.doc);
    }
    // A bound that may be left out or null.
    std::optional<double> bound(const json& j, const char* key, const std::string& ptr) {
        double x = 0.0;
        const json* v = find(j, key);
        if (!v || v->is_null() || !read(*v, field_pointer(ptr, key), x)) return std::nullopt;
        return x;
    }
    // The elements of the array `key` that are objects, with their pointers.
    template <class Each>
    void each_object(const json& j, const char* key, const std::string& ptr, Each&& each) {
        const json* a = array_field(j, key, ptr, true);
        if (!a) return;
        for (std::size_t i = 0; i < a->size(); ++i) {
            std::string p = fmt::format("{}/{}/{}", ptr, key, i);
            if (is_object((*a)[i], p)) each((*a)[i], p);
        }
    }
};

}  // namespace

json manifest_to_json(const PackManifest& m) {
    json j;
    j["version"] = m.version;
    j["name"] = m.name;
    j["compiler"] = m.compiler;
    j["graph_hash"] = m.graph_hash;
    j["precision"] = m.precision;
    if (m.animated) j["animated"] = true;
    j["effects"] = m.effects.names();
    j["params_size"] = m.params_size;
    j["params"] = json::array();
    for (const auto& p : m.params) {
        json pj{{"name", p.name}, {"type", type_name(p.type)}, {"value", constant_json(p.value)}, {"offset", p.offset},
                {"doc", p.doc}};
        if (p.min) pj["min"] = *p.min;
        if (p.max) pj["max"] = *p.max;
        j["params"].push_back(pj);
    }
    j["passes"] = json::array();
    for (const auto& p : m.passes) {
        json pj{{"name", p.name},
                {"local_size", p.local_size},
                {"push_constant_size", p.push_constant_size},
                {"spec_constants", p.spec_constants},
                {"dispatch_constants", p.dispatch_constants},
                {"bindings", json::array()}};
        for (const auto& b : p.bindings) {
            json bj{{"set", b.set}, {"binding", b.binding}, {"kind", b.kind}, {"name", b.name}, {"access", b.access}};
            if (!b.format.empty()) bj["format"] = b.format;
            pj["bindings"].push_back(bj);
        }
        j["passes"].push_back(pj);
    }
    j["spec_constants"] = json::array();
    for (const auto& s : m.spec_constants) {
        json sj{{"id", s.id}, {"name", s.name}, {"type", type_name(s.type)}, {"value", s.value}, {"doc", s.doc}};
        if (s.min) sj["min"] = *s.min;
        if (s.max) sj["max"] = *s.max;
        j["spec_constants"].push_back(sj);
    }
    j["lipschitz"] = {{"bound", m.lipschitz_bound}, {"exact", m.lipschitz_exact}, {"notes", m.lipschitz_notes}};
    j["fractals"] = json::array();
    for (const auto& f : m.fractals)
        j["fractals"].push_back({{"node", f.node},
                                 {"type", f.type},
                                 {"running_derivative", f.running_derivative},
                                 {"bias_spec", f.bias_spec},
                                 {"iterations_spec", f.iterations_spec}});
    if (m.period) j["period"] = *m.period;
    j["scene"] = scene_settings_to_json(m.scene);
    j["uniform_blocks"] = m.uniform_blocks;
    return j;
}

std::optional<PackManifest> manifest_from_json(const json& j, Diagnostics& diag) {
    ManifestReader r(diag);
    PackManifest m;
    if (!j.is_object()) {
        r.error("the manifest is not a JSON object", "");
        return std::nullopt;
    }
    std::uint32_t version = 0;
    if (r.required(j, "version", "", version) && version != static_cast<std::uint32_t>(kManifestVersion)) {
        r.error(fmt::format("manifest version {} is not supported (this build reads {})", version, kManifestVersion),
                "/version");
        return std::nullopt;
    }
    r.required(j, "name", "", m.name);
    r.required(j, "compiler", "", m.compiler);
    r.required(j, "graph_hash", "", m.graph_hash);
    // Absent in packs written before precision "double" existed: those are float.
    r.optional(j, "precision", "", m.precision, Choices{"float", "double"});
    r.optional(j, "animated", "", m.animated);
    if (const json* effects = r.array_field(j, "effects", "", true)) {
        for (std::size_t i = 0; i < effects->size(); ++i) {
            std::string ptr = fmt::format("/effects/{}", i), name;
            if (!r.read((*effects)[i], ptr, name)) continue;
            if (auto eff = parse_effect(name)) m.effects.add(*eff);
            else r.error(fmt::format("unknown effect \"{}\"", name), ptr);
        }
    }
    r.required(j, "params_size", "", m.params_size);
    std::set<std::string> param_names;
    r.each_object(j, "params", "", [&](const json& pj, const std::string& ptr) {
        ManifestParam p;
        r.declaration(pj, ptr, p);
        r.required(pj, "offset", ptr, p.offset);
        if (const json* v = r.array_field(pj, "value", ptr, true)) {
            if (static_cast<int>(v->size()) != component_count(p.type)) {
                r.error(fmt::format("value has {} components, {} needs {}", v->size(), type_name(p.type),
                                    component_count(p.type)),
                        ptr + "/value");
            } else {
                std::array<double, 4> xs{0, 0, 0, 0};
                r.read_numbers(*v, ptr + "/value", std::span<double>(xs.data(), v->size()));
                p.value = Constant::vector(p.type, xs);
            }
        }
        if (!param_names.insert(p.name).second) r.error(fmt::format("parameter \"{}\" listed twice", p.name), ptr);
        if (p.offset + 4u * static_cast<std::uint32_t>(component_count(p.type)) > m.params_size)
            r.error(fmt::format("parameter \"{}\" at offset {} lies outside the {}-byte block", p.name, p.offset,
                                m.params_size),
                    ptr + "/offset");
        m.params.push_back(p);
    });
    std::set<std::uint32_t> spec_ids;
    r.each_object(j, "spec_constants", "", [&](const json& sj, const std::string& ptr) {
        ManifestSpecConstant s;
        r.required(sj, "id", ptr, s.id);
        r.declaration(sj, ptr, s);
        r.required(sj, "value", ptr, s.value);
        if (s.id == 0) r.error("specialization constant id 0 is reserved", ptr + "/id");
        if (!spec_ids.insert(s.id).second) r.error(fmt::format("specialization constant id {} listed twice", s.id), ptr);
        if (s.type != ValueType::Float && s.type != ValueType::Int && s.type != ValueType::Bool)
            r.error("a specialization constant is float, int or bool", ptr + "/type");
        m.spec_constants.push_back(s);
    });
    std::set<std::string> pass_names;
    r.each_object(j, "passes", "", [&](const json& pj, const std::string& ptr) {
        ManifestPass p;
        r.required(pj, "name", ptr, p.name);
        r.required(pj, "push_constant_size", ptr, p.push_constant_size, NumberRange{0, 128});
        if (const json* ls = r.array_field(pj, "local_size", ptr, true)) {
            if (ls->size() != 3) r.error(fmt::format("expected 3 entries, got {}", ls->size()), ptr + "/local_size");
            else
                for (std::size_t k = 0; k < 3; ++k)
                    r.read((*ls)[k], fmt::format("{}/local_size/{}", ptr, k), p.local_size[k], NumberRange{1, 1024});
        }
        if (const json* sc = r.array_field(pj, "spec_constants", ptr, true)) {
            for (std::size_t k = 0; k < sc->size(); ++k) {
                std::string at = fmt::format("{}/spec_constants/{}", ptr, k);
                std::uint32_t id = 0;
                if (!r.read((*sc)[k], at, id)) continue;
                if (!m.find_spec(id)) r.error("refers to a specialization constant the manifest does not list", at);
                else p.spec_constants.push_back(id);
            }
        }
        // Optional: a pack from an older fgc has none, and its passes read those values themselves.
        if (const json* dc = r.array_field(pj, "dispatch_constants", ptr)) {
            for (std::size_t k = 0; k < dc->size(); ++k) {
                std::string at = fmt::format("{}/dispatch_constants/{}", ptr, k);
                std::uint32_t id = 0;
                if (!r.read((*dc)[k], at, id)) continue;
                if (!is_dispatch_constant(id)) r.error("is not a dispatch constant of this runtime (recompile the pack)", at);
                else p.dispatch_constants.push_back(id);
            }
        }
        r.each_object(pj, "bindings", ptr, [&](const json& bj, const std::string& bp) {
            ManifestBinding b;
            r.required(bj, "set", bp, b.set);
            r.required(bj, "binding", bp, b.binding);
            r.required(bj, "kind", bp, b.kind, Choices{"uniform_buffer", "storage_buffer", "storage_image", "sampled_image"});
            r.required(bj, "name", bp, b.name);
            r.optional(bj, "access", bp, b.access, Choices{"read", "write", "read_write"});
            r.optional(bj, "format", bp, b.format);
            p.bindings.push_back(b);
        });
        if (!pass_names.insert(p.name).second) r.error(fmt::format("pass \"{}\" listed twice", p.name), ptr);
        m.passes.push_back(p);
    });
    if (const json* lj = r.object_field(j, "lipschitz", "", true)) {
        r.required(*lj, "bound", "/lipschitz", m.lipschitz_bound, NumberRange::positive());
        r.optional(*lj, "exact", "/lipschitz", m.lipschitz_exact);
        if (const json* notes = r.array_field(*lj, "notes", "/lipschitz"))
            for (std::size_t i = 0; i < notes->size(); ++i)
                if (std::string n; r.read((*notes)[i], fmt::format("/lipschitz/notes/{}", i), n)) m.lipschitz_notes.push_back(n);
    }
    r.each_object(j, "fractals", "", [&](const json& fj, const std::string& ptr) {
        ManifestFractal f;
        r.required(fj, "node", ptr, f.node);
        r.required(fj, "type", ptr, f.type);
        r.required(fj, "running_derivative", ptr, f.running_derivative);
        r.required(fj, "bias_spec", ptr, f.bias_spec);
        r.required(fj, "iterations_spec", ptr, f.iterations_spec);
        if (f.bias_spec && !m.find_spec(f.bias_spec)) r.error("bias_spec names no specialization constant", ptr);
        if (f.iterations_spec && !m.find_spec(f.iterations_spec))
            r.error("iterations_spec names no specialization constant", ptr);
        m.fractals.push_back(f);
    });
    // Optional (older packs have none): three positive periods.
    if (glm::dvec3 period; r.optional(j, "period", "", period, NumberRange::positive()))
        m.period = std::array<double, 3>{period.x, period.y, period.z};
    if (const json* ub = r.object_field(j, "uniform_blocks", "", true))
        for (auto it = ub->begin(); it != ub->end(); ++it)
            r.read(it.value(), JsonFieldReader::field_pointer("/uniform_blocks", it.key()), m.uniform_blocks[it.key()],
                   NumberRange{0, 65536});
    // Decoded here, once: the runtime reads the typed settings and never the JSON.
    bool scene_ok = true;
    if (const json* sj = r.require(j, "scene", "")) {
        Diagnostics scene_diag;
        m.scene = parse_scene_settings(sj, "/manifest/scene", scene_diag);
        scene_ok = !scene_diag.has_errors();
        diag.append(scene_diag);
    }
    if (!r.ok() || !scene_ok) return std::nullopt;
    return m;
}

}  // namespace fg
