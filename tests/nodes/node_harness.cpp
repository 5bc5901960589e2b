#include "node_harness.h"

#include "codegen/double_lowering.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace fg::test {

using nlohmann::json;

std::vector<std::string> library_node_types() {
    std::vector<std::string> types;
    for (const auto* def : NodeLibrary::builtin().all())
        // Formula stages and the formula node live in a formula's body: tests/compiler/formula_test.cpp.
        if (!def->builtin_input && !def->is_stage() && !def->generated_body()) types.push_back(def->type);
    return types;
}

std::vector<std::string> library_distance_node_types() {
    std::vector<std::string> types;
    for (const auto& t : library_node_types())
        if (feeds_distance(library_node(t))) types.push_back(t);
    return types;
}

const NodeDefinition& library_node(const std::string& type) {
    const auto* def = NodeLibrary::builtin().find(type);
    if (!def) throw std::logic_error("no node " + type);
    return *def;
}

std::vector<std::optional<ValueType>> instances_of(const NodeDefinition& def) {
    if (def.generic.empty()) return {std::nullopt};
    return {def.generic.begin(), def.generic.end()};
}

ValueType concrete_type(const PortType& type, std::optional<ValueType> generic) {
    return type.concrete ? *type.concrete : generic.value_or(ValueType::Float);
}

std::string instance_name(const NodeDefinition& def, std::optional<ValueType> generic) {
    return generic ? fmt::format("{}<{}>", def.type, type_name(*generic)) : def.type;
}

bool is_iterated(const NodeDefinition& def) {
    if (!def.running_derivative.empty()) return true;
    return std::any_of(def.inputs.begin(), def.inputs.end(), [](const auto& p) { return p.knob == "iterations"; });
}

namespace {

float as_float(double x) { return static_cast<float>(x); }

// A range to draw from: the declared one where there is one, kept modest so float rounding of
// the inputs stays small (a declared [-100, 100] is tested on [-4, 4]).
std::pair<double, double> draw_range(const PortDefinition& p, bool is_int) {
    double lo = p.min.value_or(-2.0);
    double hi = p.max.value_or(p.min ? lo + 4.0 : 2.0);
    double span = is_int ? 10.0 : 8.0;
    if (lo <= 0.0 && hi >= 0.0) {
        lo = std::max(lo, -span / 2);
        hi = std::min(hi, span / 2);
    } else if (hi - lo > span) {
        hi = lo + span;
    }
    return {lo, hi};
}

glm::dvec3 unit_vector(std::mt19937& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    for (;;) {
        glm::dvec3 v(g(rng), g(rng), g(rng));
        double len = glm::length(v);
        if (len > 1e-3) return v / len;
    }
}

}  // namespace

std::vector<CpuValue> random_inputs(const NodeDefinition& def, std::optional<ValueType> generic, std::mt19937& rng) {
    std::vector<CpuValue> values;
    for (const auto& port : def.inputs) {
        ValueType t = concrete_type(port.type, generic);
        CpuValue v;
        switch (port.implicit) {
            case ImplicitSource::Position: {
                std::uniform_real_distribution<double> u(-2.0, 2.0);
                v = CpuValue::of(glm::dvec3(u(rng), u(rng), u(rng)));
                break;
            }
            case ImplicitSource::Time: v = CpuValue::of(std::uniform_real_distribution<double>(0.0, 10.0)(rng)); break;
            case ImplicitSource::LightDistance: v = CpuValue::of(std::uniform_real_distribution<double>(0.1, 10.0)(rng)); break;
            case ImplicitSource::LightSample: v = CpuValue::of(glm::dvec3(0.0)); break;   // a single frame
            case ImplicitSource::Light:
            case ImplicitSource::ToCamera:
            case ImplicitSource::Normal: v = CpuValue::of(unit_vector(rng)); break;
            case ImplicitSource::None: {
                bool is_int = t == ValueType::Int;
                auto [lo, hi] = draw_range(port, is_int);
                if (t == ValueType::Bool) {
                    v = CpuValue::of(std::uniform_int_distribution<int>(0, 1)(rng) == 1);
                } else if (is_int) {
                    v = CpuValue::of(std::uniform_int_distribution<int>(static_cast<int>(std::ceil(lo)),
                                                                        static_cast<int>(std::floor(hi)))(rng));
                } else {
                    std::uniform_real_distribution<double> u(lo, hi);
                    for (int c = 0; c < component_count(t); ++c) v.v[c] = u(rng);
                }
                break;
            }
        }
        for (int c = 0; c < 4; ++c) v.v[c] = as_float(v.v[c]);
        values.push_back(v);
    }
    return values;
}

namespace {

json constant_json(const Constant& c) {
    int n = component_count(c.type);
    if (c.type == ValueType::Bool) return c.v[0] != 0.0;
    if (c.type == ValueType::Int) return static_cast<int>(c.v[0]);
    if (n == 1) return c.v[0];
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(c.v[static_cast<std::size_t>(i)]);
    return a;
}

json param_for(ValueType t, const PortDefinition& port) {
    json p = {{"type", std::string(type_name(t))}};
    if (port.default_value && port.default_value->type == t) {
        p["default"] = constant_json(*port.default_value);
    } else if (t == ValueType::Bool) {
        p["default"] = false;
    } else if (t == ValueType::Int) {
        p["default"] = static_cast<int>(port.min.value_or(1.0));
    } else {
        double x = port.min.value_or(0.5);
        int n = component_count(t);
        p["default"] = n == 1 ? json(x) : json(std::vector<double>(static_cast<std::size_t>(n), x));
    }
    if (port.min) p["min"] = *port.min;
    if (port.max) p["max"] = *port.max;
    return p;
}

bool is_literal(const json& j) { return j.is_number() || j.is_boolean() || (j.is_array() && !j.empty() && j[0].is_number()); }

}  // namespace

bool feeds_distance(const NodeDefinition& def) {
    if (def.context != NodeContext::Any) return false;
    if (const auto* d = def.find_output("distance"); d && d->type.concrete == ValueType::Float) return true;
    const auto* p = def.find_output("p");
    return p && p->type.concrete == ValueType::Vec3;
}

json graph_around(const NodeDefinition& def, std::optional<ValueType> generic, bool with_example) {
    json nodes = json::array();
    json params = json::object();
    json inputs = json::object();
    bool varying = false;  // some input varies, so the node is not folded away at compile time
    int shapes = 0;
    const json example = with_example ? def.example.value("inputs", json::object()) : json::object();
    for (const auto& port : def.inputs) {
        ValueType t = concrete_type(port.type, generic);
        if (port.implicit == ImplicitSource::Position || port.implicit == ImplicitSource::Time) varying = true;
        if (port.implicit != ImplicitSource::None) {
            if (port.implicit != ImplicitSource::Position && port.implicit != ImplicitSource::Time) varying = true;
            continue;
        }
        if (!port.required()) {
            if (example.contains(port.name) && is_literal(example[port.name])) inputs[port.name] = example[port.name];
            continue;
        }
        varying = true;
        if (t == ValueType::Float) {
            // Two shapes a distance operator can combine: a ball and a box beside it.
            std::string id = fmt::format("shape{}", shapes);
            if (shapes++ % 2 == 0)
                nodes.push_back({{"id", id}, {"type", "prim.sphere"}, {"inputs", {{"radius", 0.7}}}});
            else {
                nodes.push_back({{"id", id + "_at"}, {"type", "xform.translate"}, {"inputs", {{"offset", {0.5, 0.2, 0.0}}}}});
                nodes.push_back({{"id", id}, {"type", "prim.box"}, {"inputs", {{"p", id + "_at.p"}, {"size", {0.4, 0.3, 0.5}}}}});
            }
            inputs[port.name] = id;
        } else if (t == ValueType::Vec3) {
            std::string id = "point_" + port.name;
            double k = static_cast<double>(nodes.size());
            nodes.push_back({{"id", id}, {"type", "xform.translate"}, {"inputs", {{"offset", {0.1 * k, 0.2, 0.3}}}}});
            inputs[port.name] = id + ".p";
        } else {
            std::string name = "in_" + port.name;
            params[name] = param_for(t, port);
            inputs[port.name] = "$" + name;
        }
    }
    if (!varying) {
        // Every input constant: the compiler would fold the node. A parameter keeps it a real call.
        for (const auto& port : def.inputs) {
            if (!port.knob.empty() || port.implicit != ImplicitSource::None) continue;
            std::string name = "in_" + port.name;
            params[name] = param_for(concrete_type(port.type, generic), port);
            inputs[port.name] = "$" + name;
            break;
        }
    }
    nodes.push_back({{"id", "n"}, {"type", def.type}, {"inputs", inputs}});

    json outputs = json::object();
    if (feeds_distance(def)) {
        if (def.find_output("distance")) {
            outputs["distance"] = "n.distance";
        } else {
            // Centred and symmetric about every coordinate plane, and smaller than half of any cell
            // the repetitions use in their examples: the shape they are documented for.
            nodes.push_back({{"id", "shape"}, {"type", "prim.box"}, {"inputs", {{"p", "n.p"}, {"size", {0.45, 0.25, 0.15}}}}});
            outputs["distance"] = "shape";
        }
    } else {
        nodes.push_back({{"id", "ground"}, {"type", "prim.sphere"}});
        outputs["distance"] = "ground";
        const auto& out = def.outputs.front();
        ValueType t = concrete_type(out.type, generic);
        std::string ref = "n." + out.name;
        if (t == ValueType::Vec3) {
            outputs["albedo"] = ref;
        } else if (t == ValueType::Vec2 || t == ValueType::Vec4) {
            nodes.push_back({{"id", "size"}, {"type", "math.length"}, {"inputs", {{"v", ref}}}});
            outputs["ao"] = "size";
        } else {
            outputs["ao"] = ref;
        }
    }
    json g = {{"format", "fractograph-graph"}, {"version", 1}, {"name", "node " + def.type},
              {"nodes", nodes},            {"outputs", outputs}};
    if (!params.empty()) g["params"] = params;
    return g;
}

namespace {

std::string read_input(ValueType t, const std::string& at) {
    switch (t) {
        case ValueType::Float: return fmt::format("fg_in.v[{}].x", at);
        case ValueType::Int: return fmt::format("int(fg_in.v[{}].x)", at);
        case ValueType::Bool: return fmt::format("(fg_in.v[{}].x != 0.0)", at);
        case ValueType::Vec2: return fmt::format("fg_in.v[{}].xy", at);
        case ValueType::Vec3: return fmt::format("fg_in.v[{}].xyz", at);
        case ValueType::Vec4: return fmt::format("fg_in.v[{}]", at);
    }
    return "0.0";
}

// The double forms: buffers of dvec4.
std::string write_output_double(ValueType t, const std::string& var) {
    switch (t) {
        case ValueType::Float: return fmt::format("dvec4({}, 0.0, 0.0, 0.0)", var);
        case ValueType::Int: return fmt::format("dvec4(double({}), 0.0, 0.0, 0.0)", var);
        case ValueType::Bool: return fmt::format("dvec4({} ? 1.0 : 0.0, 0.0, 0.0, 0.0)", var);
        case ValueType::Vec2: return fmt::format("dvec4({}, 0.0, 0.0)", var);
        case ValueType::Vec3: return fmt::format("dvec4({}, 0.0)", var);
        case ValueType::Vec4: return var;
    }
    return "dvec4(0.0)";
}

std::string write_output(ValueType t, const std::string& var) {
    switch (t) {
        case ValueType::Float: return fmt::format("vec4({}, 0.0, 0.0, 0.0)", var);
        case ValueType::Int: return fmt::format("vec4(float({}), 0.0, 0.0, 0.0)", var);
        case ValueType::Bool: return fmt::format("vec4({} ? 1.0 : 0.0, 0.0, 0.0, 0.0)", var);
        case ValueType::Vec2: return fmt::format("vec4({}, 0.0, 0.0)", var);
        case ValueType::Vec3: return fmt::format("vec4({}, 0.0)", var);
        case ValueType::Vec4: return var;
    }
    return "vec4(0.0)";
}

}  // namespace

std::string evaluation_shader(const NodeDefinition& def, std::optional<ValueType> generic, const std::string& prelude,
                              bool in_double) {
    const std::size_t nin = std::max<std::size_t>(def.inputs.size(), 1);
    const std::size_t nout = def.outputs.size();
    const char* v4 = in_double ? "dvec4" : "vec4";
    auto type = [&](ValueType t) { return in_double ? double_type_name(t) : std::string(type_name(t)); };
    std::string s = fmt::format("#version 460\n"
                                "layout(local_size_x = 64) in;\n"
                                "layout(std430, set = 0, binding = 0) readonly buffer FgIn {{ {0} v[]; }} fg_in;\n"
                                "layout(std430, set = 0, binding = 1) writeonly buffer FgOut {{ {0} v[]; }} fg_out;\n"
                                "layout(push_constant) uniform FgPush {{ uint count; }} pc;\n"
                                "#define OUT(T) out T\n#define INOUT(T) inout T\n",
                                v4);
    if (in_double) {
        s += "double fg_scene_distance_d(dvec3 p) { return length(p) - 1.0lf; }\n";
        s += lower_to_double(NodeLibrary::builtin().double_math()) + "\n" + double_math_vector_forms();
        s += lower_to_double(prelude) + "\n";
    } else {
        s += "float fg_scene_distance(vec3 p) { return length(p) - 1.0; }\n";
        s += prelude + "\n";
    }
    if (generic) s += fmt::format("#define T {}\n", type(*generic));
    s += (in_double ? lower_to_double(def.glsl) : def.glsl) + "\n";
    if (generic) s += "#undef T\n";
    s += "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= pc.count) return;\n";
    std::string args;
    for (std::size_t k = 0; k < def.inputs.size(); ++k) {
        ValueType t = concrete_type(def.inputs[k].type, generic);
        s += fmt::format("    {} in{} = {};\n", type(t), k, read_input(t, fmt::format("i * {}u + {}u", nin, k)));
        args += fmt::format("{}in{}", args.empty() ? "" : ", ", k);
    }
    for (std::size_t k = 0; k < nout; ++k) {
        s += fmt::format("    {} out{};\n", type(concrete_type(def.outputs[k].type, generic)), k);
        args += fmt::format("{}out{}", args.empty() ? "" : ", ", k);
    }
    s += fmt::format("    {}({});\n", def.function_name(), args);
    for (std::size_t k = 0; k < nout; ++k) {
        ValueType t = concrete_type(def.outputs[k].type, generic);
        s += fmt::format("    fg_out.v[i * {}u + {}u] = {};\n", nout, k,
                         in_double ? write_output_double(t, fmt::format("out{}", k)) : write_output(t, fmt::format("out{}", k)));
    }
    s += "}\n";
    return s;
}

const char* unit_sphere_scene() {
    return R"({"format": "fractograph-graph", "version": 1, "name": "unit sphere",
               "nodes": [{"id": "ball", "type": "prim.sphere", "inputs": {"radius": 1.0}}],
               "outputs": {"distance": "ball"}})";
}

}  // namespace fg::test
