#include "fgc_commands.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "compiler.h"
#include "cpu/cpu_evaluator.h"
#include "graph/node_library.h"
#include "pack/pack_reader.h"
#include "pack/pack_writer.h"
#include "spirv/pass_cache_file.h"

namespace fg {
std::span<const EmbeddedFile> embedded_node_files();
}

namespace fg::fgc {

std::optional<std::string> read_text(const std::string& path, Diagnostics& diag) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diag.error(fmt::format("cannot open {}", path));
        return std::nullopt;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

NodeLibrary library_for(const Common& c, Diagnostics& diag) {
    NodeLibrary lib = NodeLibrary::from_files(embedded_node_files(), diag);
    for (const auto& folder : c.node_folders) lib.load_folder(folder, diag);
    return lib;
}

int report(const Diagnostics& diag, const std::string& file) {
    std::string text = diag.format(file);
    if (!text.empty()) fmt::print(stderr, "{}", text);
    if (diag.has_errors()) {
        fmt::print(stderr, "{}: {} error{}\n", file, diag.error_count(), diag.error_count() == 1 ? "" : "s");
        return 1;
    }
    return 0;
}

namespace {

std::string join(const std::vector<std::string>& xs, const char* sep = ", ") {
    std::string s;
    for (std::size_t i = 0; i < xs.size(); ++i) s += (i ? sep : "") + xs[i];
    return s.empty() ? "(none)" : s;
}

void print_summary(const PackManifest& m, std::size_t bytes, const std::optional<EnvironmentImage>& sky) {
    fmt::print("pack '{}' ({}, {} bytes)\n", m.name, m.compiler, bytes);
    fmt::print("  effects:    {}\n", join(m.effects.names()));
    std::vector<std::string> passes;
    for (const auto& p : m.passes) passes.push_back(p.name);
    fmt::print("  passes:     {}\n", join(passes));
    if (m.precision == "double") fmt::print("  precision:  double (camera-relative; needs shaderFloat64)\n");
    const auto* step = m.find_spec("step_scale");
    fmt::print("  lipschitz:  {:.4g}{} (step scale {:.4g})\n", m.lipschitz_bound, m.lipschitz_exact ? "" : " (fallback)",
               step ? step->value : 1.0 / m.lipschitz_bound);
    if (m.period) fmt::print("  period:     {:g} x {:g} x {:g} (the scene repeats; the runtime wraps the head)\n", (*m.period)[0],
                             (*m.period)[1], (*m.period)[2]);
    if (const auto& env = m.scene.environment)
        fmt::print("  environment: {}\n", env->image.empty() ? std::string("a uniform sky")
                                                              : fmt::format("{} ({}x{}, in the pack)", env->image, sky ? sky->width : 0,
                                                                            sky ? sky->height : 0));
    for (const auto& f : m.fractals) {
        const auto* bias = m.find_spec(f.bias_spec);
        const auto* iters = m.find_spec(f.iterations_spec);
        fmt::print("  fractal:    {} ({}): bias {}, iterations {}\n", f.node, f.type,
                   bias ? fmt::format("{:g}", bias->value) : "param", iters ? fmt::format("{:g}", iters->value) : "param");
        if (f.type == kFormulaNodeType) fmt::print("              derived by fgc: {}\n", f.running_derivative);
    }
    for (const auto& p : m.params)
        fmt::print("  param:      {} {} = {} [{}, {}]\n", type_name(p.type), p.name, p.value.text(),
                   p.min ? fmt::format("{:g}", *p.min) : "-", p.max ? fmt::format("{:g}", *p.max) : "-");
}

}  // namespace

int check(const Common& c, const std::string& graph) {
    Diagnostics diag;
    auto lib = library_for(c, diag);
    auto text = read_text(graph, diag);
    if (!text) return report(diag, graph);
    PassCache cache(64, user_pass_cache_folder());
    CompileOptions options;
    options.cache = &cache;
    options.folder = std::filesystem::path(graph).parent_path().string();
    auto result = compile_graph(*text, lib, options, diag);
    int rc = report(diag, graph);
    if (rc == 0 && result && !c.quiet) {
        fmt::print("{}: ok: {} nodes after folding {} and removing {}; effects: {}; Lipschitz bound {:.4g}\n", graph,
                   result->ir.nodes.size(), result->folding.folded, result->folding.removed,
                   join(result->manifest.effects.names()), result->manifest.lipschitz_bound);
    }
    return rc;
}

int compile(const Common& c, const std::string& graph, const std::string& output_arg, const std::string& glsl_dir,
            bool include_glsl, bool verbose, const std::string& precision, bool optimize) {
    Diagnostics diag;
    auto lib = library_for(c, diag);
    auto text = read_text(graph, diag);
    if (!text) return report(diag, graph);
    PassCache cache(64, user_pass_cache_folder());   // passes an earlier run compiled are read from disk
    CompileOptions options;
    options.cache = &cache;
    options.folder = std::filesystem::path(graph).parent_path().string();
    options.include_glsl = include_glsl;
    options.optimize = optimize;
    if (!precision.empty()) options.double_precision = precision == "double";
    auto result = compile_graph(*text, lib, options, diag);
    if (report(diag, graph) != 0 || !result) return 1;
    std::string output = output_arg;
    if (output.empty()) output = std::filesystem::path(graph).replace_extension(".fgpack").string();
    if (!glsl_dir.empty()) {
        std::filesystem::create_directories(glsl_dir);
        for (const auto& p : result->passes) {
            std::ofstream(std::filesystem::path(glsl_dir) / (p.source.name + ".comp")) << p.source.glsl;
        }
    }
    auto bytes = pack_bytes(*result);
    std::filesystem::path parent = std::filesystem::path(output).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    Diagnostics write_diag;
    if (!write_file_atomically(output, bytes, write_diag)) return report(write_diag, graph);
    if (!c.quiet) {
        fmt::print("wrote {}\n", output);
        print_summary(result->manifest, bytes.size(), result->environment);
    }
    if (verbose) {
        const auto& t = result->times;
        fmt::print("  time:       {:.1f} ms wall; CPU time by stage: load {:.1f}, ir {:.1f}, analysis {:.1f}, codegen "
                   "{:.1f}, glslang {:.1f}, spirv-opt+val {:.1f}, reflect {:.1f}\n",
                   t.wall_ms, t.load_ms, t.ir_ms, t.analysis_ms, t.codegen_ms, t.glslang_ms, t.optimize_ms,
                   t.reflect_ms);
        fmt::print("  cache:      {} of {} passes compiled, the others read from the pass cache\n", t.passes_compiled,
                   result->passes.size());
        for (const auto& n : result->lipschitz.notes) fmt::print("  note:       {}\n", n);
    }
    return 0;
}

int info(const Common&, const std::string& path, bool json) {
    Diagnostics diag;
    auto pack = read_pack_file(path, diag);
    if (!pack) return report(diag, path);
    if (json) {
        fmt::print("{}\n", pack->manifest_json.dump(2));
        return 0;
    }
    print_summary(pack->manifest, pack->file_size, pack->environment);
    fmt::print("  format:     {}.{}, {} chunks\n", pack->version_major, pack->version_minor, pack->chunks.size());
    for (const auto& ch : pack->chunks)
        fmt::print("    {} {:<10} {:>8} bytes at {:>7}  xxh64 {:016x}\n", tag_text(ch.tag), ch.name, ch.payload_size,
                   ch.offset, ch.checksum);
    const auto& m = pack->manifest;
    fmt::print("  knobs (specialization constants):\n");
    for (const auto& s : m.spec_constants)
        fmt::print("    {:>3} {:<24} {:<5} {:g}\n", s.id, s.name, type_name(s.type), s.value);
    fmt::print("  passes:\n");
    for (const auto& p : m.passes) {
        std::vector<std::string> b;
        for (const auto& x : p.bindings) b.push_back(fmt::format("{}:{} {} {}", x.set, x.binding, x.kind, x.name));
        fmt::print("    {:<10} local {}x{}x{}, push {} B, {} SPIR-V words\n      bindings: {}\n", p.name, p.local_size[0],
                   p.local_size[1], p.local_size[2], p.push_constant_size, pack->spirv.at(p.name).size(), join(b));
    }
    return 0;
}

namespace {

std::string port_line(const PortDefinition& p, bool input) {
    std::string s = fmt::format("{} {}", p.type.text(), p.name);
    if (input) {
        if (p.implicit != ImplicitSource::None) s += fmt::format(" = <{}>", implicit_source_name(p.implicit));
        else if (p.default_value) s += " = " + p.default_value->text();
        else s += " (required)";
        if (p.min || p.max)
            s += fmt::format(" in [{}, {}]", p.min ? fmt::format("{:g}", *p.min) : "-inf",
                             p.max ? fmt::format("{:g}", *p.max) : "inf");
        if (!p.knob.empty()) s += fmt::format(" (knob: {})", p.knob);
    } else if (p.effect) {
        s += fmt::format(" (adds effect {})", effect_name(*p.effect));
    }
    return s + " - " + p.doc;
}

// Table cells cannot hold a bare '|'.
std::string cell(std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.insert(at, "\\");
    return text;
}

std::string stage_rule_text(const NodeDefinition& d) {
    switch (d.derivative.rule) {
        case StageDerivative::Rule::Isometry: return "isometry (dr unchanged)";
        case StageDerivative::Rule::Conformal: return fmt::format("conformal (dr times output {})", d.derivative.factor);
        case StageDerivative::Rule::Bound: return fmt::format("norm bound (dr times output {}, the largest stretch)", d.derivative.factor);
        case StageDerivative::Rule::Power: return fmt::format("power map (dr times output {}; log estimate)", d.derivative.factor);
        case StageDerivative::Rule::AddC: return fmt::format("add c (dr plus |{}| when c is the point)", d.derivative.weight);
        case StageDerivative::Rule::Orbit: return "none: the compiler supplies its outputs";
        case StageDerivative::Rule::None: break;
    }
    return {};
}

std::string tangent_rule_text(const NodeDefinition& d) {
    return fmt::format("tangent of {} through {}", join(d.tangent.outputs), join(d.tangent.inputs));
}

std::string markdown_node(const NodeDefinition& d) {
    std::string s = fmt::format("### `{}`\n\n{}\n\n{}\n\n", d.type, d.summary, d.doc);
    if (d.context == NodeContext::Shade) s += "*Shading only*: evaluated at the hit, never inside the march.\n\n";
    if (!d.generic.empty()) {
        std::vector<std::string> g;
        for (auto t : d.generic) g.emplace_back(type_name(t));
        s += fmt::format("Generic: `T` is one of {}.\n\n", join(g));
    }
    s += "| port | type | default | range | about |\n|---|---|---|---|---|\n";
    for (const auto& p : d.inputs) {
        std::string def = p.implicit != ImplicitSource::None ? fmt::format("*{}*", implicit_source_name(p.implicit))
                          : p.default_value                  ? p.default_value->text()
                                                             : "required";
        std::string range = (p.min || p.max) ? fmt::format("[{}, {}]", p.min ? fmt::format("{:g}", *p.min) : "-inf",
                                                           p.max ? fmt::format("{:g}", *p.max) : "inf")
                                             : "";
        std::string about = p.doc + (p.knob.empty() ? "" : fmt::format(" (knob: {})", p.knob));
        s += fmt::format("| in `{}` | {} | {} | {} | {} |\n", p.name, p.type.text(), def, range, cell(about));
    }
    for (const auto& p : d.outputs) {
        std::string about = p.doc + (p.effect ? fmt::format(" (adds effect `{}`)", effect_name(*p.effect)) : "");
        s += fmt::format("| out `{}` | {} | | | {} |\n", p.name, p.type.text(), cell(about));
    }
    s += "\n";
    if (!d.lipschitz.empty()) {
        s += "Lipschitz rule: ";
        std::vector<std::string> rules;
        for (const auto& [out, rule] : d.lipschitz) rules.push_back(fmt::format("`{}`: `{}`", out, rule));
        s += join(rules, "; ") + "\n\n";
    }
    if (!d.running_derivative.empty())
        s += fmt::format("Running derivative (guarded by the conservative bias): `{}`\n\n", d.running_derivative);
    if (d.is_stage()) s += fmt::format("Derivative, as a formula stage: {}\n\n", stage_rule_text(d));
    if (!d.tangent.empty())
        s += fmt::format("Dual-number rule, in a formula that carries the Jacobian: {}\n\n", tangent_rule_text(d));
    if (!d.effects.empty()) {
        std::vector<std::string> e;
        for (auto x : d.effects) e.emplace_back(effect_name(x));
        s += fmt::format("Adds effects: {}\n\n", join(e));
    }
    if (!d.example.is_null())
        s += fmt::format("Example:\n\n```json\n{{\"id\": \"{}\", \"type\": \"{}\", \"inputs\": {}}}\n```\n\n",
                         d.namespace_name() == "input" ? d.type.substr(6) : d.type.substr(d.type.find('.') + 1), d.type,
                         d.example.value("inputs", nlohmann::json::object()).dump());
    return s;
}

}  // namespace

int nodes(const Common& c, const std::string& type, bool markdown) {
    Diagnostics diag;
    auto lib = library_for(c, diag);
    if (diag.has_errors()) return report(diag, "node library");
    if (!type.empty() && type.find('.') == std::string::npos) {  // a namespace: its nodes
        bool any = false;
        for (const auto* d : lib.all())
            if (d->namespace_name() == type) {
                fmt::print("  {:<24} {}\n", d->type, d->summary);
                any = true;
            }
        if (any) return 0;
    }
    if (!type.empty()) {
        const auto* d = lib.find(type);
        if (!d) {
            auto near = lib.similar(type);
            fmt::print(stderr, "unknown node type \"{}\"{}\n", type, near.empty() ? "" : "; did you mean " + join(near) + "?");
            return 1;
        }
        if (markdown) {
            fmt::print("{}", markdown_node(*d));
            return 0;
        }
        fmt::print("{}\n  {}\n\n  {}\n", d->type, d->summary, d->doc);
        fmt::print("  inputs:\n");
        for (const auto& p : d->inputs) fmt::print("    {}\n", port_line(p, true));
        fmt::print("  outputs:\n");
        for (const auto& p : d->outputs) fmt::print("    {}\n", port_line(p, false));
        for (const auto& [out, rule] : d->lipschitz) fmt::print("  lipschitz {}: {}\n", out, rule);
        if (!d->running_derivative.empty()) fmt::print("  running derivative: {}\n", d->running_derivative);
        if (d->is_stage()) fmt::print("  derivative: {}\n", stage_rule_text(*d));
        if (!d->tangent.empty()) fmt::print("  tangent: {}\n", tangent_rule_text(*d));
        return 0;
    }
    if (markdown) {
        fmt::print("# Node reference\n\nGenerated by `fgc nodes --markdown` from `nodes/`; do not edit by hand.\n\n");
        fmt::print("Every input can be bound to another node's output (`\"node.port\"`), a parameter "
                   "(`\"$name\"`) or a literal. Ports marked *position*, *light*, ... take that runtime value "
                   "when left unbound.\n\n");
        std::string ns;
        for (const auto* d : lib.all()) {
            if (d->namespace_name() != ns) {
                ns = d->namespace_name();
                fmt::print("## {}\n\n", ns);
            }
            fmt::print("{}", markdown_node(*d));
        }
        return 0;
    }
    std::string ns;
    for (const auto* d : lib.all()) {
        if (d->namespace_name() != ns) {
            ns = d->namespace_name();
            fmt::print("{}\n", ns);
        }
        fmt::print("  {:<24} {}\n", d->type, d->summary);
    }
    return 0;
}

std::optional<CpuScene> load_cpu_scene(const Common& c, const std::string& graph, Diagnostics& diag) {
    auto lib = std::make_unique<NodeLibrary>(library_for(c, diag));
    auto text = read_text(graph, diag);
    if (!text) return std::nullopt;
    auto ir = load_and_lower(*text, *lib, diag);
    if (!ir) return std::nullopt;
    CpuScene scene{std::move(lib), std::make_unique<IrGraph>(std::move(*ir)), std::nullopt};
    scene.evaluator = CpuEvaluator::create(*scene.ir, diag);
    if (!scene.evaluator) return std::nullopt;
    return scene;
}

int probe(const Common& c, const std::string& graph, double x, double y, double z) {
    Diagnostics diag;
    auto scene = load_cpu_scene(c, graph, diag);
    if (!scene) return report(diag, graph);
    glm::dvec3 p(x, y, z);
    double d = scene->evaluator->distance(p);
    glm::dvec3 n = scene->evaluator->normal(p);
    fmt::print("distance {:.17g}\nnormal   {:.9f} {:.9f} {:.9f}\n", d, n.x, n.y, n.z);
    return 0;
}

}  // namespace fg::fgc
