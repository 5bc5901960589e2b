#include "scene_codegen.h"

#include "double_lowering.h"

#include <fmt/format.h>
#include <functional>
#include <optional>

namespace fg {

namespace {
SourceOrigin generated() { return {}; }
SourceOrigin from_node(const IrNode& n) {
    SourceOrigin o;
    o.kind = SourceOrigin::Kind::Node;
    o.node_id = n.id;
    o.pointer = n.pointer;
    return o;
}
}  // namespace

std::string SceneCodegen::variable(int node, int port) { return fmt::format("n{}_{}", node, port); }

std::string SceneCodegen::type_of(ValueType t) const { return double_ ? double_type_name(t) : std::string(type_name(t)); }

std::string SceneCodegen::lowered(const std::string& glsl) const { return double_ ? lower_to_double(glsl) : glsl; }

std::string SceneCodegen::in_precision(const std::string& value, ValueType t) const {
    if (!double_ || t == ValueType::Int || t == ValueType::Bool) return value;
    return fmt::format("{}({})", double_type_name(t), value);
}

void SceneCodegen::output_defines(GlslWriter& w) const {
    for (const auto& [name, _] : ir_.outputs) {
        std::string upper = name;
        for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        w.line(fmt::format("#define FG_OUT_{} 1", upper), generated());
        // Outputs computed from the direction to the camera: shading reuse recomputes them.
        if (name != "distance" && reads_to_camera(ir_.outputs.at(name)))
            w.line(fmt::format("#define FG_OUT_{}_READS_VIEW 1", upper), generated());
    }
}

namespace {
// The surface's scalar lighting terms and their values when the graph leaves them unbound: those a
// shade pass can recompute for another viewer (fg_scene_view_terms).
constexpr std::pair<const char*, const char*> kScalarTerms[] = {{"ao", "1.0"}, {"sss", "0.0"}, {"rim", "0.0"}};
}  // namespace

bool SceneCodegen::reads_to_camera(const IrInput& root) const {
    auto to_camera = [](const IrInput& in) { return in.kind == IrInput::Kind::Implicit && in.implicit == ImplicitSource::ToCamera; };
    if (to_camera(root)) return true;
    std::vector<bool> needed = needed_by({&root});
    for (std::size_t i = 0; i < ir_.nodes.size(); ++i)
        if (needed[i])
            for (const auto& in : ir_.nodes[i].inputs)
                if (to_camera(in)) return true;
    return false;
}

std::vector<const IrInput*> SceneCodegen::view_roots() const {
    std::vector<const IrInput*> roots;
    for (const auto& [name, fallback] : kScalarTerms) {
        auto it = ir_.outputs.find(name);
        if (it != ir_.outputs.end() && reads_to_camera(it->second)) roots.push_back(&it->second);
    }
    return roots;
}

void SceneCodegen::declarations(GlslWriter& w) const {
    if (!ir_.params.empty()) {
        w.line("// Graph parameters: uniforms, so editing a value never recompiles.", generated());
        w.line("layout(set = 0, binding = 2, std140) uniform FgParams {", generated());
        for (const auto& p : ir_.params) {
            SourceOrigin o;
            o.kind = SourceOrigin::Kind::Node;
            o.pointer = p.pointer;
            w.line(fmt::format("    {} {};", p.type == ValueType::Bool ? "int" : std::string(type_name(p.type)), p.name), o);
        }
        w.line("} fg_param;", generated());
        w.blank();
    }
    bool any_knob = false;
    for (const auto& n : ir_.nodes)
        for (std::size_t i = 0; i < n.inputs.size(); ++i) {
            const auto& in = n.inputs[i];
            if (in.kind != IrInput::Kind::Knob) continue;
            if (!any_knob) w.line("// Node knobs: specialization constants, swept by the benchmark without recompiling.", generated());
            any_knob = true;
            w.line(fmt::format("layout(constant_id = {}) const {} FG_KNOB_{} = {};  // {}.{}", in.knob_id,
                               type_name(in.type), in.knob_id, in.constant.glsl(), n.def->inputs[i].knob, n.id),
                   from_node(n));
        }
    if (any_knob) w.blank();
    // Node bodies declare outputs as OUT(type) so the same text compiles as C++ (a reference there).
    w.line("#define OUT(T) out T", generated());
    w.line("#define INOUT(T) inout T", generated());
    SourceOrigin prelude;
    prelude.kind = SourceOrigin::Kind::Library;
    prelude.file = "nodes/prelude.glsl";
    prelude.line = 1;
    if (double_) {
        SourceOrigin math = prelude;
        math.file = "nodes/double_math.glsl";
        w.write(lower_to_double(library_.double_math()), math);
        w.write(double_math_vector_forms(), generated());
    }
    w.write(lowered(library_.prelude()), prelude);
    w.blank();
    bodies(w, needed_by({&ir_.outputs.at("distance")}), std::vector<bool>(ir_.nodes.size(), false));
}

std::vector<bool> SceneCodegen::needed_by(const std::vector<const IrInput*>& roots) const {
    std::vector<bool> needed(ir_.nodes.size(), false);
    std::function<void(const IrInput&)> need = [&](const IrInput& in) {
        if (in.kind != IrInput::Kind::Node || needed[static_cast<std::size_t>(in.node)]) return;
        needed[static_cast<std::size_t>(in.node)] = true;
        for (const auto& sub : ir_.nodes[static_cast<std::size_t>(in.node)].inputs) need(sub);
    };
    for (const auto* r : roots) need(*r);
    return needed;
}

namespace {
bool is_volume_output(const std::string& name) { return name.starts_with("volume_"); }
}  // namespace

std::vector<const IrInput*> SceneCodegen::surface_roots() const {
    std::vector<const IrInput*> roots;
    for (const auto& [name, in] : ir_.outputs)
        if (name != "distance" && !is_volume_output(name)) roots.push_back(&in);
    return roots;
}

std::vector<const IrInput*> SceneCodegen::volume_roots() const {
    std::vector<const IrInput*> roots;
    for (const auto& [name, in] : ir_.outputs)
        if (is_volume_output(name)) roots.push_back(&in);
    return roots;
}

void SceneCodegen::bodies(GlslWriter& w, const std::vector<bool>& want, const std::vector<bool>& skip) const {
    auto instance = [](const NodeDefinition& def, std::optional<ValueType> generic) {
        return std::make_pair(def.function_name(), generic ? static_cast<int>(*generic) : -1);
    };
    auto key = [&](const IrNode& n) { return instance(*n.def, n.generic); };
    std::set<std::pair<std::string, int>> done;  // (function, generic instance)
    for (std::size_t i = 0; i < ir_.nodes.size(); ++i)
        if (skip[i]) {
            done.insert(key(ir_.nodes[i]));
            if (const auto& f = ir_.nodes[i].formula) {
                if (f->jacobian) done.insert({"jacobian", -1});
                for (const auto& [stage, generic] : f->stage_definitions()) {
                    done.insert(instance(*stage, generic));
                    if (f->jacobian) done.insert({stage->tangent_function_name(), generic ? static_cast<int>(*generic) : -1});
                }
            }
        }
    for (std::size_t i = 0; i < ir_.nodes.size(); ++i) {
        if (!want[i]) continue;
        const IrNode& n = ir_.nodes[i];
        if (n.formula) {  // the nodes its body calls (and their tangent rules), before its own function
            const bool jacobian = n.formula->jacobian;
            if (jacobian && done.insert({"jacobian", -1}).second) {
                SourceOrigin helpers;
                helpers.kind = SourceOrigin::Kind::Library;
                helpers.file = "nodes/jacobian.glsl";
                helpers.line = 1;
                w.write(lowered(library_.jacobian()), helpers);
                w.blank();
            }
            for (const auto& [stage, generic] : n.formula->stage_definitions()) {
                const bool value = done.insert(instance(*stage, generic)).second;
                const bool tangent = jacobian && done.insert({stage->tangent_function_name(), generic ? static_cast<int>(*generic) : -1}).second;
                if (!value && !tangent) continue;
                SourceOrigin body;
                body.kind = SourceOrigin::Kind::Library;
                body.file = "nodes/" + stage->glsl_path;
                body.line = 1;
                if (generic) w.line(fmt::format("#define T {}", type_of(*generic)), generated());
                if (value) w.write(lowered(stage->glsl), body);
                body.line = stage->tangent_line;
                if (tangent) w.write(lowered(stage->tangent_glsl), body);
                if (generic) w.line("#undef T", generated());
                w.blank();
            }
        }
        if (n.custom_def) {
            if (!done.insert(key(n)).second) continue;
            SourceOrigin head = from_node(n);
            std::string params;
            for (std::size_t i = 0; i < n.def->inputs.size(); ++i)
                params += fmt::format("{}{} {}", params.empty() ? "" : ", ", n.inputs[i].type == ValueType::Bool ? "bool" : type_of(n.inputs[i].type), n.def->inputs[i].name);
            for (std::size_t i = 0; i < n.def->outputs.size(); ++i)
                params += fmt::format("{}out {} {}", params.empty() ? "" : ", ", type_of(n.output_types[i]), n.def->outputs[i].name);
            w.line(fmt::format("void {}({})", n.def->function_name(), params), head);
            w.line("{", head);
            SourceOrigin code = head;
            code.pointer = n.custom_code_pointer;
            code.line = 1;
            w.write(lowered(n.custom_code), code);
            w.line("}", head);
            w.blank();
            done.insert(key(n));
            continue;
        }
        if (!done.insert(key(n)).second) continue;
        SourceOrigin body;
        body.kind = SourceOrigin::Kind::Library;
        body.file = "nodes/" + n.def->glsl_path;
        body.line = 1;
        if (n.generic) w.line(fmt::format("#define T {}", type_of(*n.generic)), generated());
        w.write(lowered(n.def->glsl), body);
        if (n.generic) w.line("#undef T", generated());
        w.blank();
    }
}

std::string SceneCodegen::value_of(const IrInput& in, Context context) const {
    const bool shading = context != Context::Distance, towards_any = context == Context::LightTerms;
    std::string v;
    switch (in.kind) {
        case IrInput::Kind::Node: v = variable(in.node, in.port); break;
        case IrInput::Kind::Param: {
            const auto& p = ir_.params[static_cast<std::size_t>(in.param)];
            v = p.type == ValueType::Bool ? fmt::format("(fg_param.{} != 0)", p.name) : in_precision("fg_param." + p.name, p.type);
            break;
        }
        case IrInput::Kind::Constant: v = lowered(in.constant.glsl()); break;
        case IrInput::Kind::Knob: v = in_precision(fmt::format("FG_KNOB_{}", in.knob_id), in.source_type); break;
        case IrInput::Kind::Implicit:
            switch (in.implicit) {
                case ImplicitSource::Position: v = "p"; break;
                case ImplicitSource::Time: v = in_precision("fg_frame.seconds", ValueType::Float); break;
                case ImplicitSource::Light: v = in_precision(towards_any ? "fg_light" : "fg_scene.light_dir.xyz", ValueType::Vec3); break;
                case ImplicitSource::LightDistance:
                    v = in_precision(towards_any ? "fg_light_distance" : fmt::format("{:g}", kDirectionalLightDistance), ValueType::Float);
                    break;
                case ImplicitSource::LightSample: v = in_precision(shading ? "fg_light_sample()" : "vec3(0.0)", ValueType::Vec3); break;
                case ImplicitSource::ToCamera: v = in_precision(shading ? "fg_to_camera" : "vec3(0.0)", ValueType::Vec3); break;
                case ImplicitSource::Normal: v = in_precision(shading ? "fg_normal" : "vec3(0.0)", ValueType::Vec3); break;
                case ImplicitSource::None: v = lowered("0.0"); break;
            }
            break;
    }
    if (in.source_type != in.type) v = fmt::format("{}({})", type_of(in.type), v);
    return v;
}

void SceneCodegen::function_body(GlslWriter& w, const std::vector<const IrInput*>& roots, Context context) const {
    std::vector<bool> needed = needed_by(roots);
    for (std::size_t i = 0; i < ir_.nodes.size(); ++i) {
        if (!needed[i]) continue;
        const auto& n = ir_.nodes[i];
        SourceOrigin o = from_node(n);
        std::string decl = "   ";
        for (std::size_t k = 0; k < n.output_types.size(); ++k)
            decl += fmt::format(" {} {};", type_of(n.output_types[k]), variable(static_cast<int>(i), static_cast<int>(k)));
        w.line(decl + fmt::format("  // {} ({})", n.id, n.def->type), o);
        std::string args;
        for (const auto& in : n.inputs) args += (args.empty() ? "" : ", ") + value_of(in, context);
        for (std::size_t k = 0; k < n.output_types.size(); ++k)
            args += (args.empty() ? "" : ", ") + variable(static_cast<int>(i), static_cast<int>(k));
        w.line(fmt::format("    {}({});", n.def->function_name(), args), o);
    }
}

void SceneCodegen::distance_function(GlslWriter& w) const {
    const auto& d = ir_.outputs.at("distance");
    w.line(double_ ? "double fg_scene_distance_d(dvec3 p)" : "float fg_scene_distance(vec3 p)", generated());
    w.line("{", generated());
    function_body(w, {&d}, Context::Distance);
    w.line(fmt::format("    return {};", value_of(d, Context::Distance)), generated());
    w.line("}", generated());
    w.blank();
    if (!double_) return;
    // The passes march in float relative to the anchor; distances near a surface are small, so
    // float keeps their relative precision.
    w.line("float fg_scene_distance(vec3 p)", generated());
    w.line("{", generated());
    w.line("    return float(fg_scene_distance_d(fg_anchor() + dvec3(p)));", generated());
    w.line("}", generated());
    w.blank();
}

void SceneCodegen::shading_function_head(GlslWriter& w, const char* name, const char* type, const char* extra_parameters) const {
    // In double precision p is relative to the anchor, and the bodies see the absolute point.
    w.line(fmt::format("{} {}(vec3 {}, vec3 fg_to_camera, vec3 fg_normal{})", type, name, double_ ? "fg_relative_p" : "p",
                       extra_parameters),
           generated());
    w.line("{", generated());
    if (double_) w.line("    dvec3 p = fg_anchor() + dvec3(fg_relative_p);", generated());
}

void SceneCodegen::surface_function(GlslWriter& w) const {
    std::vector<const IrInput*> roots = surface_roots(), volume = volume_roots();
    roots.insert(roots.end(), volume.begin(), volume.end());
    bodies(w, needed_by(roots), needed_by({&ir_.outputs.at("distance")}));
    w.line("struct FgSurface { vec3 albedo; float diffuse; float ao; float sss; float rim; vec3 emission; float shadow; "
           "vec3 specular; vec3 specular_color; float roughness; vec3 reflection; vec3 transmission; float ior; vec3 absorption; };",
           generated());
    shading_function_head(w, "fg_scene_surface");
    function_body(w, surface_roots(), Context::Surface);
    auto field = [&](const char* name, const char* fallback) { return output_or(name, fallback, Context::Surface); };
    w.line("    FgSurface s;", generated());
    w.line(fmt::format("    s.albedo = {};", field("albedo", "fg_scene.albedo.xyz")), generated());
    w.line(fmt::format("    s.diffuse = {};", field("diffuse", "0.0")), generated());
    for (const auto& [name, fallback] : kScalarTerms) w.line(fmt::format("    s.{} = {};", name, field(name, fallback)), generated());
    w.line(fmt::format("    s.emission = {};", field("emission", "vec3(0.0)")), generated());
    w.line(fmt::format("    s.shadow = {};", field("shadow", "1.0")), generated());
    w.line(fmt::format("    s.specular = {};", field("specular", "vec3(0.0)")), generated());
    w.line(fmt::format("    s.specular_color = {};", field("specular_color", "vec3(0.0)")), generated());
    w.line(fmt::format("    s.roughness = {};", field("roughness", "0.35")), generated());
    w.line(fmt::format("    s.reflection = {};", field("reflection", "vec3(0.0)")), generated());
    w.line(fmt::format("    s.transmission = {};", field("transmission", "vec3(0.0)")), generated());
    w.line(fmt::format("    s.ior = {};", field("ior", "1.5")), generated());
    w.line(fmt::format("    s.absorption = {};", field("absorption", "vec3(0.0)")), generated());
    w.line("    return s;", generated());
    w.line("}", generated());
    w.blank();
    view_terms_function(w, field);
    if (!ir_.scene.light.auxiliary.empty()) light_terms_function(w);
    if (ir_.outputs.count("volume_density")) volume_function(w);
}

void SceneCodegen::volume_function(GlslWriter& w) const {
    // A point of the medium is on no surface: it has no normal and no view (as the distance). The
    // scene's distance there comes with it, from the same node calls where the medium reads the
    // fractal (iteration fog), so the march through the medium can take its steps by it.
    w.line(double_ ? "vec4 fg_scene_volume(vec3 fg_relative_p, out float fg_distance)" : "vec4 fg_scene_volume(vec3 p, out float fg_distance)",
           generated());
    w.line("{", generated());
    if (double_) w.line("    dvec3 p = fg_anchor() + dvec3(fg_relative_p);", generated());
    std::vector<const IrInput*> roots = volume_roots();
    roots.push_back(&ir_.outputs.at("distance"));
    function_body(w, roots, Context::Distance);
    w.line(fmt::format("    fg_distance = {};", output_or("distance", "0.0", Context::Distance)), generated());
    w.line(fmt::format("    return vec4({}, {});", output_or("volume_color", "vec3(1.0)", Context::Distance),
                       output_or("volume_density", "0.0", Context::Distance)),
           generated());
    w.line("}", generated());
    w.blank();
}

std::string SceneCodegen::output_or(const char* name, const char* fallback, Context context) const {
    auto it = ir_.outputs.find(name);
    if (it == ir_.outputs.end()) return fallback;
    std::string v = value_of(it->second, context);
    return double_ ? fmt::format("{}({})", type_name(it->second.type), v) : v;
}

void SceneCodegen::light_terms_function(GlslWriter& w) const {
    // The terms that depend on the light, evaluated again for each auxiliary light: its direction
    // and distance replace the main light's in every node that reads them.
    std::vector<const IrInput*> roots;
    for (const char* name : {"diffuse", "shadow", "specular"})
        if (auto it = ir_.outputs.find(name); it != ir_.outputs.end()) roots.push_back(&it->second);
    w.line(fmt::format("#define FG_DIRECTIONAL_LIGHT_DISTANCE {:g}", kDirectionalLightDistance), generated());
    w.line("struct FgLightTerms { float diffuse; float shadow; vec3 specular; };", generated());
    shading_function_head(w, "fg_scene_light_terms", "FgLightTerms", ", vec3 fg_light, float fg_light_distance");
    function_body(w, roots, Context::LightTerms);
    w.line("    FgLightTerms l;", generated());
    w.line(fmt::format("    l.diffuse = {};", output_or("diffuse", "max(dot(fg_normal, fg_light), 0.0)", Context::LightTerms)),
           generated());
    w.line(fmt::format("    l.shadow = {};", output_or("shadow", "1.0", Context::LightTerms)), generated());
    w.line(fmt::format("    l.specular = {};", output_or("specular", "vec3(0.0)", Context::LightTerms)), generated());
    w.line("    return l;", generated());
    w.line("}", generated());
    w.blank();
}

void SceneCodegen::view_terms_function(GlslWriter& w, const std::function<std::string(const char*, const char*)>& field) const {
    // Only the scalar terms that read the view: the shade pass adds them to a colour shaded from
    // another point of view (FG_OUT_AO_READS_VIEW and the like say which); the rest keep defaults.
    auto view = [&](const char* name, const char* fallback) {
        auto it = ir_.outputs.find(name);
        return it != ir_.outputs.end() && reads_to_camera(it->second) ? field(name, fallback) : std::string(fallback);
    };
    shading_function_head(w, "fg_scene_view_terms");
    function_body(w, view_roots(), Context::Surface);
    w.line("    FgSurface s = FgSurface(vec3(0.0), 0.0, 1.0, 0.0, 0.0, vec3(0.0), 1.0, vec3(0.0), vec3(0.0), 0.35, vec3(0.0), vec3(0.0), 1.5, vec3(0.0));", generated());
    for (const auto& [name, fallback] : kScalarTerms) w.line(fmt::format("    s.{} = {};", name, view(name, fallback)), generated());
    w.line("    return s;", generated());
    w.line("}", generated());
    w.blank();
}

void SceneCodegen::trap_function(GlslWriter& w) const {
    std::vector<bool> needed = needed_by({&ir_.outputs.at("distance")});
    std::optional<IrInput> trap;
    for (std::size_t i = 0; i < ir_.nodes.size() && !trap; ++i) {
        const auto& outputs = ir_.nodes[i].def->outputs;
        for (std::size_t k = 0; k < outputs.size() && needed[i]; ++k)
            if (outputs[k].name == "trap" && ir_.nodes[i].output_types[k] == ValueType::Vec4) {
                trap = IrInput{};
                trap->kind = IrInput::Kind::Node;
                trap->node = static_cast<int>(i);
                trap->port = static_cast<int>(k);
                trap->type = trap->source_type = ValueType::Vec4;
                break;
            }
    }
    if (trap) w.line("#define FG_HAS_TRAP_OUTPUT 1", generated());
    // The fractal's body is already there (the distance needs it): this calls it once more.
    w.line(double_ ? "vec4 fg_scene_trap(vec3 fg_relative_p)" : "vec4 fg_scene_trap(vec3 p)", generated());
    w.line("{", generated());
    if (!trap) {
        w.line("    return vec4(0.0);", generated());
    } else {
        if (double_) w.line("    dvec3 p = fg_anchor() + dvec3(fg_relative_p);", generated());
        function_body(w, {&*trap}, Context::Distance);
        w.line(fmt::format("    return vec4({});", value_of(*trap, Context::Distance)), generated());
    }
    w.line("}", generated());
    w.blank();
}

}  // namespace fg
