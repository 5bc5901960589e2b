#include "manifest.h"

#include <cmath>
#include <fmt/format.h>
#include <set>

#include "graph/scene_settings.h"

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

// Field readers that report "/manifest/<pointer>: expected ..." and keep going.
struct Reader {
    Diagnostics& diag;
    bool ok = true;

    void fail(const std::string& msg, const std::string& ptr) {
        diag.error("manifest: " + msg, "/manifest" + ptr);
        ok = false;
    }
    const json* field(const json& j, const char* key, const std::string& ptr) {
        if (!j.is_object() || !j.contains(key)) {
            fail(fmt::format("missing \"{}\"", key), ptr);
            return nullptr;
        }
        return &j[key];
    }
    std::string str(const json& j, const char* key, const std::string& ptr) {
        auto* f = field(j, key, ptr);
        if (!f) return {};
        if (!f->is_string()) {
            fail(fmt::format("\"{}\" must be a string", key), ptr + "/" + key);
            return {};
        }
        return f->get<std::string>();
    }
    double num(const json& j, const char* key, const std::string& ptr) {
        auto* f = field(j, key, ptr);
        if (!f) return 0;
        if (!f->is_number() || !std::isfinite(f->get<double>())) {
            fail(fmt::format("\"{}\" must be a finite number", key), ptr + "/" + key);
            return 0;
        }
        return f->get<double>();
    }
    std::uint32_t u32(const json& j, const char* key, const std::string& ptr) {
        auto* f = field(j, key, ptr);
        if (!f) return 0;
        if (!f->is_number_unsigned() || f->get<std::uint64_t>() > 0xffffffffull) {
            fail(fmt::format("\"{}\" must be an unsigned 32-bit integer", key), ptr + "/" + key);
            return 0;
        }
        return f->get<std::uint32_t>();
    }
    const json* array(const json& j, const char* key, const std::string& ptr) {
        auto* f = field(j, key, ptr);
        if (f && !f->is_array()) {
            fail(fmt::format("\"{}\" must be an array", key), ptr + "/" + key);
            return nullptr;
        }
        return f;
    }
    ValueType type(const json& j, const char* key, const std::string& ptr) {
        auto s = str(j, key, ptr);
        auto t = parse_type(s);
        if (!t && !s.empty()) fail(fmt::format("unknown type \"{}\"", s), ptr + "/" + key);
        return t.value_or(ValueType::Float);
    }
    std::optional<double> opt_num(const json& j, const char* key, const std::string& ptr) {
        if (!j.contains(key) || j[key].is_null()) return std::nullopt;
        return num(j, key, ptr);
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
                {"bindings", json::array()}};
        for (const auto& b : p.bindings)
            pj["bindings"].push_back(
                {{"set", b.set}, {"binding", b.binding}, {"kind", b.kind}, {"name", b.name}, {"access", b.access}});
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
    j["scene"] = m.scene;
    j["uniform_blocks"] = m.uniform_blocks;
    return j;
}

std::optional<PackManifest> manifest_from_json(const json& j, Diagnostics& diag) {
    Reader r{diag};
    PackManifest m;
    if (!j.is_object()) {
        r.fail("the manifest is not a JSON object", "");
        return std::nullopt;
    }
    auto version = r.u32(j, "version", "");
    if (r.ok && version != static_cast<std::uint32_t>(kManifestVersion)) {
        r.fail(fmt::format("manifest version {} is not supported (this build reads {})", version, kManifestVersion),
               "/version");
        return std::nullopt;
    }
    m.name = r.str(j, "name", "");
    m.compiler = r.str(j, "compiler", "");
    m.graph_hash = r.str(j, "graph_hash", "");
    // Absent in packs written before precision "double" existed: those are float.
    if (j.contains("precision")) {
        m.precision = r.str(j, "precision", "");
        if (r.ok && m.precision != "float" && m.precision != "double")
            r.fail("precision must be \"float\" or \"double\"", "/precision");
    }
    if (auto* effects = r.array(j, "effects", "")) {
        for (std::size_t i = 0; i < effects->size(); ++i) {
            const auto& e = (*effects)[i];
            auto eff = e.is_string() ? parse_effect(e.get<std::string>()) : std::nullopt;
            if (!eff) r.fail("unknown effect", fmt::format("/effects/{}", i));
            else m.effects.add(*eff);
        }
    }
    m.params_size = r.u32(j, "params_size", "");
    if (auto* params = r.array(j, "params", "")) {
        std::set<std::string> names;
        for (std::size_t i = 0; i < params->size(); ++i) {
            std::string ptr = fmt::format("/params/{}", i);
            const auto& pj = (*params)[i];
            ManifestParam p;
            p.name = r.str(pj, "name", ptr);
            p.type = r.type(pj, "type", ptr);
            p.offset = r.u32(pj, "offset", ptr);
            p.min = r.opt_num(pj, "min", ptr);
            p.max = r.opt_num(pj, "max", ptr);
            if (pj.contains("doc") && pj["doc"].is_string()) p.doc = pj["doc"].get<std::string>();
            if (auto* v = r.array(pj, "value", ptr)) {
                if (static_cast<int>(v->size()) != component_count(p.type)) {
                    r.fail(fmt::format("value has {} components, {} needs {}", v->size(), type_name(p.type),
                                       component_count(p.type)),
                           ptr + "/value");
                } else {
                    std::array<double, 4> xs{0, 0, 0, 0};
                    for (std::size_t k = 0; k < v->size(); ++k) {
                        if (!(*v)[k].is_number() || !std::isfinite((*v)[k].get<double>()))
                            r.fail("value components must be finite numbers", fmt::format("{}/value/{}", ptr, k));
                        else
                            xs[k] = (*v)[k].get<double>();
                    }
                    p.value = Constant::vector(p.type, xs);
                }
            }
            if (!names.insert(p.name).second) r.fail(fmt::format("parameter \"{}\" listed twice", p.name), ptr);
            if (p.offset + 4u * static_cast<std::uint32_t>(component_count(p.type)) > m.params_size)
                r.fail(fmt::format("parameter \"{}\" at offset {} lies outside the {}-byte block", p.name, p.offset,
                                   m.params_size),
                       ptr + "/offset");
            m.params.push_back(p);
        }
    }
    if (auto* specs = r.array(j, "spec_constants", "")) {
        std::set<std::uint32_t> ids;
        for (std::size_t i = 0; i < specs->size(); ++i) {
            std::string ptr = fmt::format("/spec_constants/{}", i);
            const auto& sj = (*specs)[i];
            ManifestSpecConstant s;
            s.id = r.u32(sj, "id", ptr);
            s.name = r.str(sj, "name", ptr);
            s.type = r.type(sj, "type", ptr);
            s.value = r.num(sj, "value", ptr);
            s.min = r.opt_num(sj, "min", ptr);
            s.max = r.opt_num(sj, "max", ptr);
            if (sj.contains("doc") && sj["doc"].is_string()) s.doc = sj["doc"].get<std::string>();
            if (s.id == 0) r.fail("specialization constant id 0 is reserved", ptr + "/id");
            if (!ids.insert(s.id).second) r.fail(fmt::format("specialization constant id {} listed twice", s.id), ptr);
            if (s.type != ValueType::Float && s.type != ValueType::Int && s.type != ValueType::Bool)
                r.fail("a specialization constant is float, int or bool", ptr + "/type");
            m.spec_constants.push_back(s);
        }
    }
    if (auto* passes = r.array(j, "passes", "")) {
        std::set<std::string> names;
        for (std::size_t i = 0; i < passes->size(); ++i) {
            std::string ptr = fmt::format("/passes/{}", i);
            const auto& pj = (*passes)[i];
            ManifestPass p;
            p.name = r.str(pj, "name", ptr);
            p.push_constant_size = r.u32(pj, "push_constant_size", ptr);
            if (p.push_constant_size > 128) r.fail("push constants larger than 128 bytes", ptr + "/push_constant_size");
            if (auto* ls = r.array(pj, "local_size", ptr)) {
                if (ls->size() != 3) r.fail("local_size has 3 entries", ptr + "/local_size");
                else
                    for (std::size_t k = 0; k < 3; ++k) {
                        if (!(*ls)[k].is_number_unsigned() || (*ls)[k].get<std::uint64_t>() == 0 ||
                            (*ls)[k].get<std::uint64_t>() > 1024)
                            r.fail("local_size entries are 1..1024", fmt::format("{}/local_size/{}", ptr, k));
                        else
                            p.local_size[k] = (*ls)[k].get<std::uint32_t>();
                    }
            }
            if (auto* sc = r.array(pj, "spec_constants", ptr)) {
                for (std::size_t k = 0; k < sc->size(); ++k) {
                    const auto& idj = (*sc)[k];
                    if (!idj.is_number_unsigned() || idj.get<std::uint64_t>() > 0xffffffffull ||
                        !m.find_spec(idj.get<std::uint32_t>()))
                        r.fail("refers to a specialization constant the manifest does not list",
                               fmt::format("{}/spec_constants/{}", ptr, k));
                    else
                        p.spec_constants.push_back(idj.get<std::uint32_t>());
                }
            }
            if (auto* bs = r.array(pj, "bindings", ptr)) {
                static const std::set<std::string> kinds{"uniform_buffer", "storage_buffer", "storage_image",
                                                         "sampled_image"};
                for (std::size_t k = 0; k < bs->size(); ++k) {
                    std::string bp = fmt::format("{}/bindings/{}", ptr, k);
                    ManifestBinding b;
                    b.set = r.u32((*bs)[k], "set", bp);
                    b.binding = r.u32((*bs)[k], "binding", bp);
                    b.kind = r.str((*bs)[k], "kind", bp);
                    b.name = r.str((*bs)[k], "name", bp);
                    if (!b.kind.empty() && !kinds.count(b.kind)) r.fail(fmt::format("unknown binding kind \"{}\"", b.kind), bp);
                    if ((*bs)[k].contains("access")) {
                        b.access = r.str((*bs)[k], "access", bp);
                        if (b.access != "read" && b.access != "write" && b.access != "read_write")
                            r.fail(fmt::format("access is \"read\", \"write\" or \"read_write\", not \"{}\"", b.access),
                                   bp + "/access");
                    }
                    p.bindings.push_back(b);
                }
            }
            if (!names.insert(p.name).second) r.fail(fmt::format("pass \"{}\" listed twice", p.name), ptr);
            m.passes.push_back(p);
        }
    }
    if (auto* lj = r.field(j, "lipschitz", "")) {
        m.lipschitz_bound = r.num(*lj, "bound", "/lipschitz");
        if (m.lipschitz_bound <= 0) r.fail("the Lipschitz bound must be positive", "/lipschitz/bound");
        if (lj->contains("exact") && (*lj)["exact"].is_boolean()) m.lipschitz_exact = (*lj)["exact"].get<bool>();
        if (lj->contains("notes") && (*lj)["notes"].is_array())
            for (const auto& n : (*lj)["notes"])
                if (n.is_string()) m.lipschitz_notes.push_back(n.get<std::string>());
    }
    if (auto* fr = r.array(j, "fractals", "")) {
        for (std::size_t i = 0; i < fr->size(); ++i) {
            std::string ptr = fmt::format("/fractals/{}", i);
            ManifestFractal f;
            f.node = r.str((*fr)[i], "node", ptr);
            f.type = r.str((*fr)[i], "type", ptr);
            f.running_derivative = r.str((*fr)[i], "running_derivative", ptr);
            f.bias_spec = r.u32((*fr)[i], "bias_spec", ptr);
            f.iterations_spec = r.u32((*fr)[i], "iterations_spec", ptr);
            if (f.bias_spec && !m.find_spec(f.bias_spec)) r.fail("bias_spec names no specialization constant", ptr);
            if (f.iterations_spec && !m.find_spec(f.iterations_spec))
                r.fail("iterations_spec names no specialization constant", ptr);
            m.fractals.push_back(f);
        }
    }
    // Optional (older packs have none): three positive periods.
    if (auto it = j.find("period"); it != j.end()) {
        std::array<double, 3> period{};
        bool good = it->is_array() && it->size() == 3;
        for (std::size_t i = 0; good && i < 3; ++i) {
            good = (*it)[i].is_number() && (*it)[i].get<double>() > 0.0 && std::isfinite((*it)[i].get<double>());
            if (good) period[i] = (*it)[i].get<double>();
        }
        if (good) m.period = period;
        else r.fail("\"period\" must be three positive numbers", "/period");
    }
    if (auto* ub = r.field(j, "uniform_blocks", "")) {
        if (!ub->is_object()) r.fail("\"uniform_blocks\" must be an object of name -> size", "/uniform_blocks");
        else
            for (auto it = ub->begin(); it != ub->end(); ++it) {
                if (!it.value().is_number_unsigned() || it.value().get<std::uint64_t>() > 65536)
                    r.fail("a block size is an unsigned integer up to 65536", "/uniform_blocks/" + it.key());
                else
                    m.uniform_blocks[it.key()] = it.value().get<std::uint32_t>();
            }
    }
    if (auto* sj = r.field(j, "scene", "")) {
        Diagnostics scene_diag;
        parse_scene_settings(sj, "/manifest/scene", scene_diag);
        if (scene_diag.has_errors()) {
            for (const auto& d : scene_diag.items()) diag.add(d);
            r.ok = false;
        }
        m.scene = *sj;
    }
    if (!r.ok) return std::nullopt;
    return m;
}

}  // namespace fg
