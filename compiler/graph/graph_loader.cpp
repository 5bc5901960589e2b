#include "graph_loader.h"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "common/json_fields.h"
#include "identifiers.h"
#include "json_text.h"
#include "literal.h"
#include "port_reader.h"
#include "upgrade.h"

namespace fg {

namespace {

using nlohmann::json;

std::string join(const std::vector<std::string>& xs) {
    std::string s;
    for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? ", " : "") + xs[i];
    return s;
}

class GraphReader {
public:
    GraphReader(const NodeLibrary& lib, Diagnostics& diag) : lib_(lib), diag_(diag), fields_(diag) {}

    std::optional<Graph> read(const json& doc) {
        Graph g;
        g.source = doc;
        fields_.unknown_keys(doc, "", {"format", "version", "name", "description", "params", "nodes", "outputs", "scene",
                                       "comment", "ui", "editor"},
                             "top-level field");
        fields_.optional(doc, "name", "", g.name);
        fields_.optional(doc, "description", "", g.description);
        read_params(doc, g);
        read_nodes(doc, g);
        read_outputs(doc, g);
        g.scene = parse_scene_settings(doc.contains("scene") ? &doc["scene"] : nullptr, "/scene", diag_);
        check_references(g);
        check_cycles(g);
        if (diag_.has_errors()) return std::nullopt;
        return g;
    }

private:
    const NodeLibrary& lib_;
    Diagnostics& diag_;
    JsonFieldReader fields_;
    std::string body_owner_;  // the formula node whose body is being read

    // The fields of node `id`: its problems carry the node's id.
    JsonFieldReader node_fields(const std::string& id) {
        return JsonFieldReader([this, id](const std::string& message, const std::string& pointer) {
            diag_.error(message, pointer, id);
        });
    }

    void read_params(const json& doc, Graph& g) {
        const json* params = fields_.object_field(doc, "params", "");
        if (!params) return;
        const json& ps = *params;
        for (auto it = ps.begin(); it != ps.end(); ++it) {
            std::string ptr = "/params/" + it.key();
            ParamDecl p;
            p.name = it.key();
            p.pointer = ptr;
            if (!is_valid_identifier(p.name)) {
                diag_.error(fmt::format("parameter name \"{}\" is not a valid identifier (lower case, digits, '_') "
                                        "or is reserved",
                                        p.name),
                            ptr);
                continue;
            }
            const json& pj = it.value();
            if (!fields_.is_object(pj, ptr)) continue;
            fields_.unknown_keys(pj, ptr, {"type", "default", "min", "max", "doc"});
            if (!fields_.required(pj, "type", ptr, p.type)) continue;
            for (const char* bound : {"min", "max"})
                if (double x = 0.0; fields_.optional(pj, bound, ptr, x)) (bound == std::string("min") ? p.min : p.max) = x;
            if (p.min && p.max && *p.min > *p.max) diag_.error("min is greater than max", ptr + "/min");
            fields_.optional(pj, "doc", ptr, p.doc);
            if (!pj.contains("default")) {
                diag_.error("parameter needs a \"default\" value", ptr);
                continue;
            }
            LiteralSite site{ptr + "/default", {}};
            auto c = read_literal(pj["default"], site, diag_);
            if (!c) continue;
            auto cc = coerce_literal(*c, p.type, site, diag_);
            if (!cc || !check_range(*cc, p.min, p.max, site, diag_)) continue;
            p.value = *cc;
            g.params.push_back(std::move(p));
        }
    }

    std::optional<Binding> read_binding(const json& j, const std::string& ptr, const std::string& node_id) {
        Binding b;
        b.pointer = ptr;
        auto from_reference = [&](const std::string& s) -> std::optional<Binding> {
            if (s.empty()) {
                diag_.error("empty reference: use \"node\", \"node.port\" or \"$param\"", ptr, node_id);
                return std::nullopt;
            }
            if (s[0] == '$') {
                b.kind = Binding::Kind::Param;
                b.param = s.substr(1);
                return b;
            }
            b.kind = Binding::Kind::Node;
            auto dot = s.find('.');
            b.node = s.substr(0, dot);
            if (dot != std::string::npos) b.port = s.substr(dot + 1);
            return b;
        };
        if (j.is_string()) return from_reference(j.get<std::string>());
        if (j.is_object()) {
            if (j.contains("node") && j["node"].is_string()) {
                auto r = from_reference(j["node"].get<std::string>());
                if (r) node_fields(node_id).optional(j, "port", ptr, r->port);
                return r;
            }
            if (j.contains("param") && j["param"].is_string()) {
                b.kind = Binding::Kind::Param;
                b.param = j["param"].get<std::string>();
                return b;
            }
            if (j.contains("value")) {
                auto c = read_literal(j["value"], {ptr + "/value", node_id}, diag_);
                if (!c) return std::nullopt;
                b.literal = *c;
                return b;
            }
            diag_.error("a binding object has \"node\" (and \"port\"), \"param\" or \"value\"", ptr, node_id);
            return std::nullopt;
        }
        auto c = read_literal(j, {ptr, node_id}, diag_);
        if (!c) return std::nullopt;
        b.literal = *c;
        return b;
    }

    std::optional<CustomCode> read_custom(const json& nj, const std::string& ptr, const std::string& id) {
        CustomCode c;
        auto report = [&](const std::string& m, const std::string& at) { diag_.error(m, at, id); };
        JsonFieldReader fields = node_fields(id);
        if (!nj.contains("ports")) {
            report("a custom.glsl node declares \"ports\": {\"inputs\": [...], \"outputs\": [...]}", ptr);
            return std::nullopt;
        }
        const json* ports = fields.object_field(nj, "ports", ptr);
        if (!ports) return std::nullopt;
        fields.unknown_keys(*ports, ptr + "/ports", {"inputs", "outputs"});
        std::set<std::string> names;
        for (const char* side : {"inputs", "outputs"}) {
            bool is_input = side == std::string("inputs");
            const json* list = fields.array_field(*ports, side, ptr + "/ports");
            if (!list) continue;
            for (std::size_t i = 0; i < list->size(); ++i) {
                std::string pp = fmt::format("{}/ports/{}/{}", ptr, side, i);
                auto p = read_port_definition((*list)[i], pp, is_input, false, false, report);
                if (!p) continue;
                if (!names.insert(p->name).second) report(fmt::format("port \"{}\" declared twice", p->name), pp);
                if (!p->knob.empty()) report("custom nodes have no knobs", pp + "/knob");
                (is_input ? c.inputs : c.outputs).push_back(*p);
            }
        }
        if (c.outputs.empty()) report("a custom.glsl node declares at least one output", ptr + "/ports/outputs");
        c.code_pointer = ptr + "/code";
        if (!nj.contains("code")) {
            report("a custom.glsl node needs \"code\": the GLSL statements of its body", ptr);
        } else if (nj["code"].is_string()) {
            c.code = nj["code"].get<std::string>();
        } else if (nj["code"].is_array()) {
            for (std::size_t i = 0; i < nj["code"].size(); ++i)
                if (std::string line; fields.read(nj["code"][i], fmt::format("{}/code/{}", ptr, i), line)) c.code += line + "\n";
        } else {
            report(fmt::format("expected a string or an array of lines, got {}", json_kind(nj["code"])), ptr + "/code");
        }
        // Guard against code that would break out of the generated function.
        int depth = 0;
        for (char ch : c.code) {
            depth += ch == '{' ? 1 : ch == '}' ? -1 : 0;
            if (depth < 0) break;
        }
        if (depth != 0) report("unbalanced braces in code", ptr + "/code");
        if (!nj.contains("lipschitz")) {
            report("a custom.glsl node must declare its Lipschitz bound: \"lipschitz\": 1.0 (a factor) or a rule such "
                   "as \"L(p) * 2\"",
                   ptr);
        } else if (double k = 1.0; nj["lipschitz"].is_number()) {
            fields.read(nj["lipschitz"], ptr + "/lipschitz", k, NumberRange::positive());
            // A factor k means: every output changes at most k times as fast as the fastest input.
            std::string rule = "0";
            for (const auto& in : c.inputs) rule = fmt::format("max({}, L({}))", rule, in.name);
            c.lipschitz = fmt::format("{} * {}", k, rule);
        } else if (nj["lipschitz"].is_string()) {
            c.lipschitz = nj["lipschitz"].get<std::string>();
        } else {
            report(fmt::format("expected a number (a factor) or a rule string, got {}", json_kind(nj["lipschitz"])),
                   ptr + "/lipschitz");
        }
        return c;
    }

    void read_nodes(const json& doc, Graph& g) {
        if (!doc.contains("nodes")) {
            diag_.error("missing \"nodes\": the graph has no nodes", "");
            return;
        }
        const json* nodes = fields_.array_field(doc, "nodes", "");
        if (!nodes) return;
        std::set<std::string> ids;
        for (std::size_t i = 0; i < nodes->size(); ++i)
            if (auto n = read_node((*nodes)[i], fmt::format("/nodes/{}", i), ids, false)) g.nodes.push_back(std::move(*n));
    }

    // One node of the graph, or of a formula body (`in_body`: stage nodes whose z and c may be left
    // unbound, meaning the orbit point entering the group and the formula's c).
    std::optional<GraphNode> read_node(const json& nj, const std::string& ptr, std::set<std::string>& ids, bool in_body) {
        if (!fields_.is_object(nj, ptr)) return std::nullopt;
        GraphNode n;
        n.pointer = ptr;
        if (!fields_.required(nj, "id", ptr, n.id)) return std::nullopt;
        // A body's problems belong to its formula node, the node an editor draws.
        const std::string who = in_body ? body_owner_ : n.id;
        if (!is_valid_node_id(n.id)) {
            diag_.error(fmt::format("node id \"{}\" may use only letters, digits, '_' and '-'", n.id), ptr + "/id", who);
            return std::nullopt;
        }
        if (!ids.insert(n.id).second) {
            diag_.error(fmt::format("duplicate node id \"{}\"", n.id), ptr + "/id", who);
            return std::nullopt;
        }
        JsonFieldReader fields = node_fields(who);
        if (!fields.required(nj, "type", ptr, n.type)) return std::nullopt;
        const bool custom = n.type == kCustomNodeType, formula = n.type == kFormulaNodeType;
        if (custom)
            fields.unknown_keys(nj, ptr, {"id", "type", "inputs", "comment", "ui", "ports", "code", "lipschitz"},
                                "node field");
        else if (formula && !in_body)
            fields.unknown_keys(nj, ptr, {"id", "type", "inputs", "comment", "ui", "formula"}, "node field");
        else
            fields.unknown_keys(nj, ptr, {"id", "type", "inputs", "comment", "ui"}, "node field");
        const NodeDefinition* def = nullptr;
        if (custom && !in_body) {
            n.custom = read_custom(nj, ptr, who);
        } else {
            def = lib_.find(n.type);
            if (!def) {
                auto near = lib_.similar(n.type);
                diag_.error(fmt::format("unknown node type \"{}\"{}", n.type,
                                        near.empty() ? " (fgc nodes lists them)" : "; did you mean " + join(near) + "?"),
                            ptr + "/type", who);
            } else if (in_body ? !def->fits_in_formula_body() : def->is_stage()) {
                diag_.error(in_body ? fmt::format("a formula body holds stage.* nodes and maths nodes with a tangent rule, "
                                                  "and {} is neither (fgc nodes stage and fgc nodes math list them)",
                                                  n.type)
                                    : fmt::format("{} is a formula stage: it works only inside the body of a {} node",
                                                  n.type, kFormulaNodeType),
                            ptr + "/type", who);
                def = nullptr;
            }
        }
        if (formula && !in_body) {
            if (!nj.contains("formula")) diag_.error("a fractal.formula node needs its \"formula\": groups of stages", ptr, who);
            else n.formula = read_formula(nj["formula"], ptr + "/formula", n.id);
        }
        if (const json* inputs = fields.object_field(nj, "inputs", ptr)) {
            const json& ins = *inputs;
            for (auto it = ins.begin(); it != ins.end(); ++it) {
                std::string ip = ptr + "/inputs/" + it.key();
                const PortDefinition* port = nullptr;
                if (def) port = def->find_input(it.key());
                if (n.custom)
                    for (const auto& p : n.custom->inputs)
                        if (p.name == it.key()) port = &p;
                if ((def || n.custom) && !port) {
                    std::vector<std::string> names;
                    for (const auto& p : def ? def->inputs : n.custom->inputs) names.push_back(p.name);
                    diag_.error(fmt::format("{} has no input \"{}\"; its inputs are: {}", n.type, it.key(),
                                            names.empty() ? "(none)" : join(names)),
                                ip, who);
                    continue;
                }
                auto b = read_binding(it.value(), ip, who);
                if (!b) continue;
                if (b->kind == Binding::Kind::Literal && port) {
                    LiteralSite site{ip, who};
                    if (port->type.concrete) {
                        auto c = coerce_literal(b->literal, *port->type.concrete, site, diag_);
                        if (!c || !check_range(*c, port->min, port->max, site, diag_)) continue;
                        b->literal = *c;
                    } else if (!check_range(b->literal, port->min, port->max, site, diag_)) {
                        continue;
                    }
                }
                n.inputs[it.key()] = *b;
            }
        }
        if (def || n.custom) {
            for (const auto& p : def ? def->inputs : n.custom->inputs)
                if (p.required() && !n.inputs.count(p.name) && !(in_body && def && def->is_stage() && (p.name == "z" || p.name == "c")))
                    diag_.error(fmt::format("missing required input \"{}\" ({}) of {}", p.name, p.type.text(), n.type),
                                ptr + "/inputs", who);
        }
        return n;
    }

    // "formula": {"groups": [{"name", "nodes", "z"}], "schedule": [{"group", "count"}], "repeat",
    // "julia", "estimate", "bound_radius"}
    std::shared_ptr<const FormulaBody> read_formula(const json& fj, const std::string& ptr, const std::string& id) {
        JsonFieldReader fields = node_fields(id);
        if (!fields.is_object(fj, ptr)) return nullptr;
        fields.unknown_keys(fj, ptr,
                            {"groups", "schedule", "repeat", "julia", "estimate", "derivative", "sheet_radius",
                             "linear_radius", "filled", "bound_radius", "comment"},
                            "formula field");
        auto body = std::make_shared<FormulaBody>();
        body->pointer = ptr;
        body_owner_ = id;
        fields.optional(fj, "repeat", ptr, body->repeat);
        fields.optional(fj, "julia", ptr, body->julia);
        fields.optional(fj, "estimate", ptr, body->estimate, Choices{"linear", "log", "box", "sheet"});
        fields.optional(fj, "derivative", ptr, body->derivative, Choices{"scalar", "jacobian"});
        fields.optional(fj, "sheet_radius", ptr, body->sheet_radius, NumberRange{0.0});
        fields.optional(fj, "linear_radius", ptr, body->linear_radius, NumberRange{0.0});
        fields.optional(fj, "filled", ptr, body->filled);
        fields.optional(fj, "bound_radius", ptr, body->bound_radius, NumberRange{0.0});
        std::set<std::string> ids;  // node ids are unique across the body's groups
        if (const json* groups = fields.array_field(fj, "groups", ptr, true)) {
            if (groups->empty()) diag_.error("a formula has at least one group of stages", ptr + "/groups", id);
            for (std::size_t gi = 0; gi < groups->size(); ++gi) {
                std::string gp = fmt::format("{}/groups/{}", ptr, gi);
                const json& gj = (*groups)[gi];
                if (!fields.is_object(gj, gp)) continue;
                fields.unknown_keys(gj, gp, {"name", "nodes", "z", "comment"}, "group field");
                FormulaGroup group;
                group.pointer = gp;
                if (!fields.required(gj, "name", gp, group.name)) continue;
                for (const auto& other : body->groups)
                    if (other.name == group.name)
                        diag_.error(fmt::format("two groups are named \"{}\"", group.name), gp + "/name", id);
                if (const json* nodes = fields.array_field(gj, "nodes", gp, true)) {
                    for (std::size_t i = 0; i < nodes->size(); ++i)
                        if (auto n = read_node((*nodes)[i], fmt::format("{}/nodes/{}", gp, i), ids, true))
                            group.nodes.push_back(std::move(*n));
                    if (nodes->empty()) diag_.error("a group has at least one stage", gp + "/nodes", id);
                }
                if (!group.nodes.empty()) group.z_node = group.nodes.back().id;
                fields.optional(gj, "z", gp, group.z_node);
                check_group(group, id);
                body->groups.push_back(std::move(group));
            }
        }
        if (const json* schedule = fields.array_field(fj, "schedule", ptr)) {
            for (std::size_t si = 0; si < schedule->size(); ++si) {
                std::string sp = fmt::format("{}/schedule/{}", ptr, si);
                const json& sj = (*schedule)[si];
                if (!fields.is_object(sj, sp)) continue;
                fields.unknown_keys(sj, sp, {"group", "count"}, "schedule field");
                FormulaSegment seg;
                seg.pointer = sp;
                if (!fields.required(sj, "group", sp, seg.group)) continue;
                std::int64_t count = 0;
                fields.optional(sj, "count", sp, count, NumberRange{1.0, 1000.0});
                seg.count = static_cast<int>(count);
                if (std::none_of(body->groups.begin(), body->groups.end(), [&](auto& g) { return g.name == seg.group; })) {
                    std::vector<std::string> names;
                    for (const auto& g : body->groups) names.push_back(g.name);
                    diag_.error(fmt::format("no group \"{}\"; the groups are: {}", seg.group, join(names)), sp + "/group", id);
                }
                if (seg.count == 0 && si + 1 < schedule->size())
                    diag_.error("only the last segment may leave out \"count\" (it runs every iteration left)", sp, id);
                body->schedule.push_back(seg);
            }
        } else if (body->groups.size() > 1) {
            diag_.error("a formula of several groups needs a \"schedule\": [{\"group\": ..., \"count\": ...}, ...]", ptr, id);
        }
        return body;
    }

    // Within a group every wire comes from a node of the same group, names one of its outputs, and
    // no node depends on itself. Types and what moves with the orbit are checked when the body is
    // resolved (ir/formula_program.cpp).
    void check_group(const FormulaGroup& group, const std::string& id) {
        std::map<std::string, const GraphNode*> by_id;
        for (const auto& n : group.nodes) by_id[n.id] = &n;
        if (!group.z_node.empty() && !by_id.count(group.z_node))
            diag_.error(fmt::format("\"z\" names node \"{}\", which is not in this group", group.z_node),
                        group.pointer + "/z", id);
        bool wiring_ok = true;
        for (const auto& n : group.nodes)
            for (const auto& [port, b] : n.inputs) {
                if (b.kind != Binding::Kind::Node) continue;
                auto src = by_id.find(b.node);
                if (src == by_id.end()) {
                    diag_.error(fmt::format("\"{}\" is not a node of this group (leave a stage's z unbound for the point "
                                            "entering the group, or read it from a stage.orbit node)",
                                            b.node),
                                b.pointer, id);
                    wiring_ok = false;
                } else if (const NodeDefinition* d = lib_.find(src->second->type); d && !b.port.empty() && !d->find_output(b.port)) {
                    std::vector<std::string> names;
                    for (const auto& o : d->outputs) names.push_back(o.name);
                    diag_.error(fmt::format("{} has no output \"{}\"; its outputs are: {}", d->type, b.port, join(names)),
                                b.pointer, id);
                    wiring_ok = false;
                }
            }
        if (!wiring_ok) return;
        // Depth-first: a node met again while its own inputs are being followed closes a cycle.
        std::map<std::string, int> state;  // 1: being followed, 2: done
        std::function<bool(const GraphNode&)> visit = [&](const GraphNode& n) {
            state[n.id] = 1;
            for (const auto& [port, b] : n.inputs) {
                if (b.kind != Binding::Kind::Node) continue;
                int& s = state[b.node];
                if (s == 1) {
                    diag_.error(fmt::format("cycle: node \"{}\" takes its input \"{}\" from itself through the chain",
                                            n.id, port),
                                b.pointer, id);
                    return false;
                }
                if (s == 0 && !visit(*by_id[b.node])) return false;
            }
            state[n.id] = 2;
            return true;
        };
        for (const auto& n : group.nodes)
            if (state[n.id] == 0 && !visit(n)) return;
    }

    void read_outputs(const json& doc, Graph& g) {
        if (!doc.contains("outputs")) {
            diag_.error("missing \"outputs\": the graph must bind at least \"distance\"", "/outputs");
            return;
        }
        const json* outputs = fields_.object_field(doc, "outputs", "");
        if (!outputs) return;
        const json& os = *outputs;
        for (auto it = os.begin(); it != os.end(); ++it) {
            std::string ptr = "/outputs/" + it.key();
            const GraphOutputSpec* spec = nullptr;
            for (const auto& s : graph_output_specs())
                if (it.key() == s.name) spec = &s;
            if (!spec) {
                std::vector<std::string> names;
                for (const auto& s : graph_output_specs()) names.push_back(s.name);
                diag_.error(fmt::format("unknown output \"{}\"; outputs are: {}", it.key(), join(names)), ptr);
                continue;
            }
            auto b = read_binding(it.value(), ptr, {});
            if (!b) continue;
            if (b->kind == Binding::Kind::Literal) {
                auto c = coerce_literal(b->literal, spec->type, {ptr, {}}, diag_);
                if (!c) continue;
                b->literal = *c;
            }
            g.outputs[it.key()] = *b;
        }
        for (const auto& s : graph_output_specs())
            if (s.required && !os.contains(s.name))
                diag_.error(fmt::format("missing required output \"{}\" ({})", s.name, s.doc), "/outputs");
        if (os.contains("volume_color") && !os.contains("volume_density"))
            diag_.error("output \"volume_color\" colours a medium whose density is unbound: bind \"volume_density\" too "
                        "(light.iteration_fog's density)",
                        "/outputs/volume_color");
        if (os.contains("roughness") && !os.contains("specular_color"))
            diag_.error("output \"roughness\" shapes a specular lobe whose reflectance is unbound: bind \"specular_color\" too "
                        "(light.specular's specular_color)",
                        "/outputs/roughness");
    }

    // Every reference names an existing node and output port, or an existing param.
    void check_binding(const Graph& g, const Binding& b, const std::string& node_id) {
        if (b.kind == Binding::Kind::Param) {
            if (!g.find_param(b.param)) {
                std::vector<std::string> names;
                for (const auto& p : g.params) names.push_back(p.name);
                diag_.error(fmt::format("unknown parameter \"${}\"{}", b.param,
                                        names.empty() ? " (the graph declares no params)" : "; params are: " + join(names)),
                            b.pointer, node_id);
            }
            return;
        }
        if (b.kind != Binding::Kind::Node) return;
        const GraphNode* src = g.find_node(b.node);
        if (!src) {
            diag_.error(fmt::format("unknown node \"{}\" (write \"$name\" for a parameter)", b.node), b.pointer, node_id);
            return;
        }
        if (b.port.empty()) return;
        std::vector<std::string> names;
        if (const NodeDefinition* def = lib_.find(src->type))
            for (const auto& p : def->outputs) names.push_back(p.name);
        else if (src->custom)
            for (const auto& p : src->custom->outputs) names.push_back(p.name);
        else
            return;  // unknown type: already reported
        if (std::find(names.begin(), names.end(), b.port) == names.end())
            diag_.error(fmt::format("node \"{}\" ({}) has no output \"{}\"; its outputs are: {}", b.node, src->type,
                                    b.port, join(names)),
                        b.pointer, node_id);
    }

    void check_references(const Graph& g) {
        for (const auto& n : g.nodes) {
            for (const auto& [_, b] : n.inputs) check_binding(g, b, n.id);
            if (n.formula)  // a body's own wiring is checked by check_group
                for (const auto& group : n.formula->groups)
                    for (const auto& stage : group.nodes)
                        for (const auto& [_, b] : stage.inputs)
                            if (b.kind == Binding::Kind::Param) check_binding(g, b, n.id);
        }
        for (const auto& [_, b] : g.outputs) check_binding(g, b, {});
    }

    void check_cycles(const Graph& g) {
        std::map<std::string, int> state;  // 0 unvisited, 1 on stack, 2 done
        std::vector<std::string> stack;
        std::set<std::string> reported;
        std::function<void(const GraphNode&)> visit = [&](const GraphNode& n) {
            state[n.id] = 1;
            stack.push_back(n.id);
            for (const auto& [port, b] : n.inputs) {
                if (b.kind != Binding::Kind::Node) continue;
                const GraphNode* src = g.find_node(b.node);
                if (!src) continue;
                if (state[src->id] == 1) {
                    auto start = std::find(stack.begin(), stack.end(), src->id);
                    std::string path;
                    for (auto it = start; it != stack.end(); ++it) path += *it + " -> ";
                    path += src->id;
                    if (reported.insert(src->id).second)
                        diag_.error(fmt::format("cycle: {} (a graph must not feed a node's output back into itself)",
                                                path),
                                    b.pointer, n.id);
                } else if (state[src->id] == 0) {
                    visit(*src);
                }
            }
            stack.pop_back();
            state[n.id] = 2;
        };
        for (const auto& n : g.nodes)
            if (state[n.id] == 0) visit(n);
    }
};

}  // namespace

std::optional<Graph> load_graph(std::string_view json_text, const NodeLibrary& library, Diagnostics& diag) {
    auto doc = parse_json_text(json_text, diag);
    if (!doc) return std::nullopt;
    if (!doc->is_object()) {
        diag.error(fmt::format("a graph is a JSON object, not {}", doc->type_name()), "");
        return std::nullopt;
    }
    if (!doc->contains("format") || (*doc)["format"] != kGraphFormat) {
        diag.error(fmt::format("not a Fractograph graph: expected \"format\": \"{}\"", kGraphFormat), "/format");
        return std::nullopt;
    }
    std::int64_t version = 0;
    if (!JsonFieldReader(diag).required(*doc, "version", "", version)) return std::nullopt;
    if (version > kGraphVersion) {
        diag.error(fmt::format("graph format version {} is newer than this fgc understands (up to {}); update "
                               "Fractograph",
                               version, kGraphVersion),
                   "/version");
        return std::nullopt;
    }
    if (version < 1) {
        diag.error(fmt::format("graph format version {} does not exist (versions start at 1)", version), "/version");
        return std::nullopt;
    }
    if (!upgrade_graph(*doc, static_cast<int>(version), diag)) return std::nullopt;
    GraphReader reader(library, diag);
    return reader.read(*doc);
}

std::optional<Graph> load_graph_file(const std::string& path, const NodeLibrary& library, Diagnostics& diag) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diag.error(fmt::format("cannot open {}", path));
        return std::nullopt;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return load_graph(ss.str(), library, diag);
}

}  // namespace fg
