#include "node_library.h"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <set>
#include <sstream>

#include "common/edit_distance.h"
#include "common/json_fields.h"
#include "identifiers.h"
#include "json_text.h"
#include "port_reader.h"

namespace fg {

std::span<const EmbeddedFile> embedded_node_files();  // generated from nodes/ (nodes/CMakeLists.txt)

using nlohmann::json;

namespace {

// "derivative": {"rule": ..., "factor": output, "weight": input}; a stage's first input and first
// output are its orbit point z (vec3).
void read_stage_derivative(const json& d, NodeDefinition& def, JsonFieldReader& r) {
    using Rule = StageDerivative::Rule;
    r.unknown_keys(d, "/derivative", {"rule", "factor", "weight"});
    std::string rule;
    if (!r.required(d, "rule", "/derivative", rule,
                    Choices{"isometry", "conformal", "bound", "power", "add_c", "orbit"}))
        return;
    auto& sd = def.derivative;
    if (rule == "orbit") {  // stage.orbit: outputs only, supplied by the compiler
        sd.rule = Rule::Orbit;
        if (!def.inputs.empty()) r.error("an orbit source has no inputs", "/inputs");
        return;
    }
    sd.rule = rule == "isometry"    ? Rule::Isometry
              : rule == "conformal" ? Rule::Conformal
              : rule == "bound"     ? Rule::Bound
              : rule == "power"     ? Rule::Power
                                    : Rule::AddC;
    if (sd.rule == Rule::Conformal || sd.rule == Rule::Bound || sd.rule == Rule::Power) {
        if (r.required(d, "factor", "/derivative", sd.factor)) {
            const PortDefinition* out = def.find_output(sd.factor);
            if (!out || out->type.concrete != ValueType::Float)
                r.error(fmt::format("\"factor\" names a float output, and \"{}\" is none", sd.factor), "/derivative/factor");
        }
    }
    if (sd.rule == Rule::AddC) {
        if (r.required(d, "weight", "/derivative", sd.weight)) {
            const PortDefinition* in = def.find_input(sd.weight);
            if (!in || in->type.concrete != ValueType::Float)
                r.error(fmt::format("\"weight\" names a float input, and \"{}\" is none", sd.weight), "/derivative/weight");
        }
        if (!def.find_input("c") || def.find_input("c")->type.text() != def.inputs[0].type.text())
            r.error("an add_c stage has an input \"c\" of z's type", "/inputs");
    }
    // z: vec3, vec4 (quaternion stages), or T for stages that work on either.
    auto z_type = [](const std::vector<PortDefinition>& ports) -> std::string {
        return !ports.empty() && ports[0].name == "z" ? ports[0].type.text() : "";
    };
    const std::string zin = z_type(def.inputs), zout = z_type(def.outputs);
    if (zin != zout || (zin != "vec3" && zin != "vec4" && zin != "T"))
        r.error("a stage's first input and first output are \"z\", both vec3, vec4 or T", "/inputs");
    for (ValueType t : def.generic)
        if (t != ValueType::Vec3 && t != ValueType::Vec4) r.error("a generic stage works on vec3 and vec4 orbits", "/generic");
}

// "tangent": {"inputs": [...], "outputs": [...]}: ports of float and vector types.
void read_tangent_rule(const json& t, NodeDefinition& def, JsonFieldReader& r) {
    r.unknown_keys(t, "/tangent", {"inputs", "outputs"});
    for (const char* side : {"inputs", "outputs"}) {
        const bool is_input = side == std::string("inputs");
        const json* names = r.array_field(t, side, "/tangent", true);
        if (!names) continue;
        auto& list = is_input ? def.tangent.inputs : def.tangent.outputs;
        for (std::size_t i = 0; i < names->size(); ++i) {
            std::string at = fmt::format("/tangent/{}/{}", side, i), name;
            if (!r.read((*names)[i], at, name)) continue;
            const PortDefinition* port = is_input ? def.find_input(name) : def.find_output(name);
            if (!port) r.error(fmt::format("no {} \"{}\"", is_input ? "input" : "output", name), at);
            else if (port->type.concrete && !is_float_like(*port->type.concrete))
                r.error(fmt::format("\"{}\" is {}: only float and vector ports have tangents", name, port->type.text()), at);
            else list.push_back(name);
        }
    }
    if (def.tangent.outputs.empty()) r.error("a tangent rule names at least one output", "/tangent/outputs");
}

}  // namespace

std::unique_ptr<NodeDefinition> parse_node_definition(const std::string& json_path, std::string_view json_text,
                                                      Diagnostics& diag) {
    Diagnostics parse_diag;
    auto parsed = parse_json_text(json_text, parse_diag);
    for (auto d : parse_diag.items()) {
        d.message = json_path + ": " + d.message;
        diag.add(d);
    }
    if (!parsed) return nullptr;
    const json& j = *parsed;
    std::size_t errors_before = diag.error_count();
    // Every problem names the definition file first.
    JsonFieldReader r([&](const std::string& message, const std::string& pointer) {
        diag.error(fmt::format("{}: {}", json_path, message), pointer);
    });
    if (!r.is_object(j, "")) return nullptr;
    r.unknown_keys(j, "", {"type", "summary", "doc", "context", "inputs", "outputs", "generic", "lipschitz",
                           "running_derivative", "derivative", "tangent", "effects", "example"});

    auto def = std::make_unique<NodeDefinition>();
    def->json_path = json_path;
    r.required(j, "type", "", def->type);
    auto dot = def->type.find('.');
    if (!def->type.empty() && (dot == std::string::npos || dot == 0 || dot + 1 == def->type.size() ||
                               !is_valid_node_id(def->type.substr(0, dot)) ||
                               def->type.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_.") != std::string::npos))
        r.error(fmt::format("type \"{}\" must be namespace.name in lower case", def->type), "/type");
    r.required(j, "summary", "", def->summary);
    r.required(j, "doc", "", def->doc);
    std::string context;
    if (r.optional(j, "context", "", context, Choices{"any", "shade"}) && context == "shade") def->context = NodeContext::Shade;
    def->builtin_input = def->namespace_name() == "input";

    if (const json* generic = r.array_field(j, "generic", ""))
        for (std::size_t i = 0; i < generic->size(); ++i)
            if (ValueType t; r.read((*generic)[i], fmt::format("/generic/{}", i), t)) def->generic.push_back(t);
    for (const char* side : {"inputs", "outputs"}) {
        bool is_input = side == std::string("inputs");
        const json* ports = r.array_field(j, side, "", !is_input);
        if (!ports) continue;
        std::set<std::string> names;
        for (std::size_t i = 0; i < ports->size(); ++i) {
            std::string ptr = fmt::format("/{}/{}", side, i);
            auto p = read_port_definition((*ports)[i], ptr, is_input, !def->generic.empty(), true,
                                          [&r](const std::string& m, const std::string& at) { r.error(m, at); });
            if (!p) continue;
            if (!names.insert(p->name).second) r.error(fmt::format("port \"{}\" declared twice", p->name), ptr + "/name");
            (is_input ? def->inputs : def->outputs).push_back(*p);
        }
    }
    if (def->outputs.empty() && j.contains("outputs")) r.error("a node has at least one output", "/outputs");

    if (const json* l = JsonFieldReader::find(j, "lipschitz")) {
        // One rule for every output, or a rule per output.
        if (l->is_string()) {
            for (const auto& out : def->outputs) def->lipschitz[out.name] = l->get<std::string>();
        } else if (l->is_object()) {
            for (auto it = l->begin(); it != l->end(); ++it) {
                const std::string at = JsonFieldReader::field_pointer("/lipschitz", it.key());
                if (!def->find_output(it.key())) r.error(fmt::format("no output \"{}\"", it.key()), at);
                else r.read(it.value(), at, def->lipschitz[it.key()]);
            }
        } else {
            r.error(fmt::format("expected a rule string or an object of output -> rule, got {}", json_kind(*l)), "/lipschitz");
        }
    }
    r.optional(j, "running_derivative", "", def->running_derivative);
    if (!def->running_derivative.empty()) {
        bool has_bias = std::any_of(def->inputs.begin(), def->inputs.end(), [](auto& p) { return p.knob == "bias"; });
        if (!has_bias) r.error("a node with a running derivative needs an input with \"knob\": \"bias\"", "/inputs");
    }
    if (const json* d = r.object_field(j, "derivative", "")) read_stage_derivative(*d, *def, r);
    if (const json* t = r.object_field(j, "tangent", "")) read_tangent_rule(*t, *def, r);
    if (def->namespace_name() == "stage" && !def->is_stage())
        r.error("a stage.* node declares its \"derivative\": {\"rule\": \"isometry\" | \"conformal\" | \"bound\" | \"power\" | \"add_c\"}", "");
    if (const json* effects = r.array_field(j, "effects", ""))
        for (std::size_t i = 0; i < effects->size(); ++i) {
            std::string ptr = fmt::format("/effects/{}", i), name;
            if (!r.read((*effects)[i], ptr, name)) continue;
            if (auto eff = parse_effect(name)) def->effects.push_back(*eff);
            else r.error(fmt::format("unknown effect \"{}\"", name), ptr);
        }
    if (j.contains("example")) def->example = j["example"];
    if (diag.error_count() != errors_before) return nullptr;
    return def;
}

NodeLibrary NodeLibrary::from_files(std::span<const EmbeddedFile> files, Diagnostics& diag) {
    NodeLibrary lib;
    std::map<std::string, std::string_view> bodies;
    for (const auto& f : files) {
        std::string path(f.path);
        if (path.ends_with("prelude.glsl")) lib.prelude_ += std::string(f.text);
        else if (path.ends_with("double_math.glsl")) lib.double_math_ += std::string(f.text);
        else if (path.ends_with("jacobian.glsl")) lib.jacobian_ += std::string(f.text);
        else if (path.ends_with(".glsl")) bodies[path.substr(0, path.size() - 5)] = f.text;
    }
    for (const auto& f : files) {
        std::string path(f.path);
        if (!path.ends_with(".json")) continue;
        std::string stem = path.substr(0, path.size() - 5);
        auto body = bodies.find(stem);
        lib.add_definition(path, f.text, stem + ".glsl", body == bodies.end() ? std::string() : std::string(body->second),
                           diag);
    }
    return lib;
}

void NodeLibrary::add_definition(const std::string& json_path, std::string_view json_text, std::string glsl_path,
                                 std::string glsl_text, Diagnostics& diag) {
    auto def = parse_node_definition(json_path, json_text, diag);
    if (!def) return;
    if (def->has_glsl_body()) {
        if (glsl_text.empty()) {
            diag.error(fmt::format("{}: no GLSL body {} beside the definition", json_path, glsl_path));
            return;
        }
        if (glsl_text.find(def->function_name()) == std::string::npos) {
            diag.error(fmt::format("{}: the body does not define {}()", glsl_path, def->function_name()));
            return;
        }
        if (!def->tangent.empty()) {
            // Kept apart, so that only formulas carrying a Jacobian compile it.
            std::size_t at = glsl_text.find("void " + def->tangent_function_name() + "(");
            if (at == std::string::npos) {
                diag.error(fmt::format("{}: the definition has a tangent rule, and the body does not define {}() last",
                                       glsl_path, def->tangent_function_name()));
                return;
            }
            def->tangent_glsl = glsl_text.substr(at);
            def->tangent_line = 1 + static_cast<int>(std::count(glsl_text.begin(), glsl_text.begin() + static_cast<long>(at), '\n'));
            glsl_text.erase(glsl_text.find_last_not_of(" \n", at == 0 ? 0 : at - 1) + 1);
            glsl_text += "\n";
        }
    }
    def->glsl = std::move(glsl_text);
    def->glsl_path = std::move(glsl_path);
    if (defs_.count(def->type)) {
        diag.error(fmt::format("{}: node type {} is already defined by {}", json_path, def->type,
                               defs_[def->type]->json_path));
        return;
    }
    std::string type = def->type;
    defs_[type] = std::move(def);
}

void NodeLibrary::load_folder(const std::string& folder, Diagnostics& diag) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        diag.error(fmt::format("node folder {} does not exist", folder));
        return;
    }
    auto read = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    for (const auto& entry : fs::recursive_directory_iterator(folder, ec)) {
        if (entry.path().extension() != ".json") continue;
        auto glsl = entry.path();
        glsl.replace_extension(".glsl");
        add_definition(entry.path().string(), read(entry.path()), glsl.string(),
                       fs::exists(glsl) ? read(glsl) : std::string(), diag);
    }
}

const NodeLibrary& NodeLibrary::builtin() {
    static const NodeLibrary lib = [] {
        Diagnostics diag;
        auto l = from_files(embedded_node_files(), diag);
        if (diag.has_errors()) {
            fmt::print(stderr, "fractograph: the built-in node library is broken:\n{}", diag.format());
            std::abort();
        }
        return l;
    }();
    return lib;
}

const NodeDefinition* NodeLibrary::find(const std::string& type) const {
    auto it = defs_.find(type);
    return it == defs_.end() ? nullptr : it->second.get();
}

std::vector<const NodeDefinition*> NodeLibrary::all() const {
    std::vector<const NodeDefinition*> out;
    for (const auto& [_, d] : defs_) out.push_back(d.get());
    return out;
}

std::vector<std::string> NodeLibrary::similar(const std::string& type) const {
    std::vector<std::pair<std::size_t, std::string>> scored;
    auto name_of = [](const std::string& t) { return t.substr(t.find('.') + 1); };
    for (const auto& [t, _] : defs_) {
        std::size_t d = std::min(edit_distance(type, t), edit_distance(name_of(type), name_of(t)));
        if (d <= 3) scored.emplace_back(d, t);
    }
    std::sort(scored.begin(), scored.end());
    std::vector<std::string> out;
    for (std::size_t i = 0; i < scored.size() && i < 3; ++i) out.push_back(scored[i].second);
    return out;
}

}  // namespace fg
