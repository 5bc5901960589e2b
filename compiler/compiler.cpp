#include "compiler.h"

#include "codegen/double_lowering.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <thread>
#include <fmt/format.h>
#include <xxhash.h>

#include "analysis/effect_set.h"
#include "analysis/periodicity.h"
#include "analysis/precision_advice.h"
#include "analysis/specialization.h"
#include "codegen/scene_codegen.h"
#include "import/environment_exr.h"
#include "common/spec_constants.h"
#include "graph/graph_loader.h"
#include "ir/ir_builder.h"
#include "pack/pack_chunk.h"
#include "pack/pack_writer.h"
#include "spirv/glsl_compiler.h"
#include "spirv/reflection.h"
#include "spirv/spirv_optimizer.h"

namespace fg {

namespace {

class Stopwatch {
public:
    double lap() {
        auto now = std::chrono::steady_clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

struct PassBuild {
    CompiledPass pass;
    std::optional<PassReflection> reflection;
    Diagnostics diag;
    StageTimes times;
};

// One pass from template to reflected, validated SPIR-V, or from the cache when its GLSL is one
// compiled before. Runs on its own thread.
PassBuild build_pass(const PassTemplate& tmpl, const EffectSet& effects, const SceneCodegen& scene,
                     const std::vector<ManifestSpecConstant>& spec, const CompileOptions& options) {
    PassBuild b;
    Stopwatch clock;
    b.pass.source = assemble_pass(tmpl, effects, scene, spec);
    b.times.codegen_ms = clock.lap();
    const std::uint64_t key = PassCache::key(tmpl.name, b.pass.source.glsl, options.optimize);
    if (options.cache)
        if (auto cached = options.cache->find(key)) {
            b.pass.spirv = std::move(cached->spirv);
            b.reflection = std::move(cached->reflection);
            b.diag = std::move(cached->diag);
            return b;
        }
    b.times.passes_compiled = 1;
    auto spirv = compile_glsl(tmpl.name, b.pass.source.glsl, b.pass.source.source_map, b.diag);
    b.times.glslang_ms = clock.lap();
    if (!spirv) return b;
    if (options.optimize) {
        spirv = optimize_spirv(tmpl.name, *spirv, b.diag);
        if (!spirv) return b;
    }
    if (!validate_spirv(tmpl.name, *spirv, b.diag)) return b;
    b.times.optimize_ms = clock.lap();
    b.reflection = reflect_spirv(tmpl.name, *spirv, b.diag);
    b.times.reflect_ms = clock.lap();
    b.pass.spirv = std::move(*spirv);
    if (options.cache && b.reflection) options.cache->store(key, {b.pass.spirv, *b.reflection, b.diag});
    return b;
}

}  // namespace

// Precision "double" rewrites every body the scene uses; one that calls a function without a double
// form (bit casts, derivatives, noise, hyperbolic functions) cannot be lowered: say which node.
static void check_double_lowering(const IrGraph& ir, Diagnostics& diag) {
    for (const auto& n : ir.nodes) {
        std::string text = n.custom_def ? n.custom_code : n.def->glsl;
        if (n.formula)
            for (const auto& [stage, generic] : n.formula->stage_definitions()) text += stage->glsl;
        for (const auto& f : functions_without_double(text))
            diag.error(fmt::format("node '{}' ({}) cannot be evaluated in double precision (scene.precision): it calls "
                                   "{}(), which has no double form; use precision \"float\" or another node",
                                   n.id, n.def->type, f),
                       n.pointer, n.id);
    }
}

std::string content_hash(std::string_view text) { return fmt::format("{:016x}", XXH64(text.data(), text.size(), 0)); }

std::vector<std::uint32_t> std140_offsets(const std::vector<ValueType>& members, std::uint32_t& size) {
    std::vector<std::uint32_t> offsets;
    std::uint32_t at = 0;
    for (auto t : members) {
        std::uint32_t n = static_cast<std::uint32_t>(component_count(t));
        std::uint32_t align = n == 1 ? 4u : n == 2 ? 8u : 16u;
        at = (at + align - 1) / align * align;
        offsets.push_back(at);
        at += 4 * n;
    }
    size = (at + 15) / 16 * 16;
    return offsets;
}

std::optional<IrGraph> load_and_lower(std::string_view graph_text, const NodeLibrary& library, Diagnostics& diag,
                                      FoldingStats* folding) {
    auto graph = load_graph(graph_text, library, diag);
    if (!graph) return std::nullopt;
    auto ir = build_ir(*graph, library, diag);
    if (!ir) return std::nullopt;
    auto stats = fold_constants(*ir, diag);
    if (folding) *folding = stats;
    if (diag.has_errors()) return std::nullopt;
    return ir;
}

std::optional<CompileResult> compile_graph(std::string_view graph_text, const NodeLibrary& library,
                                           const CompileOptions& options, Diagnostics& diag) {
    CompileResult result;
    Stopwatch total_clock;
    result.graph_text = std::string(graph_text);
    result.include_glsl = options.include_glsl;
    Stopwatch clock;
    auto graph = load_graph(graph_text, library, diag);
    result.times.load_ms = clock.lap();
    if (!graph) return std::nullopt;
    auto ir = build_ir(*graph, library, diag);
    if (!ir) return std::nullopt;
    result.folding = fold_constants(*ir, diag);
    if (diag.has_errors()) return std::nullopt;
    result.times.ir_ms = clock.lap();

    if (options.double_precision) ir->scene.double_precision = *options.double_precision;
    if (ir->scene.double_precision) check_double_lowering(*ir, diag);
    if (diag.has_errors()) return std::nullopt;
    advise_precision(*ir, diag);

    // Analyses.
    EffectSet effects = find_effects(*ir);
    if (ir->outputs.count("specular_color") && !effects.has(Effect::Environment))
        diag.warning("output \"specular_color\" reflects the environment in the specular lobe, and the scene has none: "
                     "add scene.environment (an image or a colour), or leave the output unbound",
                     "/outputs/specular_color");
    result.lipschitz = analyse_lipschitz(*ir, diag);
    if (diag.has_errors()) return std::nullopt;
    // The calibrated step factor (fgc calibrate) shortens every step beyond 1 / L; the step fraction
    // too, and the shaders' hit tests divide it back out.
    auto spec = assign_specialization(*ir, ir->scene.step_factor * ir->scene.step_fraction / result.lipschitz.bound);
    result.times.analysis_ms = clock.lap();

    PackManifest& m = result.manifest;
    m.name = graph->name.empty() ? "untitled" : graph->name;
    m.compiler = fmt::format("fgc {}", kCompilerVersion);
    m.graph_hash = content_hash(graph_text);
    m.effects = effects;
    m.spec_constants = spec.constants;
    m.fractals = spec.fractals;
    m.lipschitz_bound = result.lipschitz.bound;
    m.lipschitz_exact = result.lipschitz.exact;
    m.lipschitz_notes = result.lipschitz.notes;
    if (ir->scene.step_factor != 1.0)
        m.lipschitz_notes.push_back(fmt::format("step factor {:g} from the graph (fgc calibrate): step scale {:g}",
                                                ir->scene.step_factor, ir->scene.step_factor / result.lipschitz.bound));
    if (ir->scene.step_fraction != 1.0)
        m.lipschitz_notes.push_back(fmt::format("step fraction {:g} from the graph: steps advance that share of the "
                                                "estimate, hit tests read all of it",
                                                ir->scene.step_fraction));
    m.period = analyse_periodicity(*ir).period;
    m.scene = ir->scene;
    if (ir->scene.environment && !ir->scene.environment->image.empty()) {
        const std::string& name = ir->scene.environment->image;
        const std::filesystem::path named = std::filesystem::path(name).lexically_normal();
        if (options.folder_confined && (named.is_absolute() || named.empty() || *named.begin() == "..")) {
            diag.error(fmt::format("scene.environment.image: '{}' is outside the graph's folder", name), "/scene/environment/image");
            return std::nullopt;
        }
        const std::string path = options.folder.empty() ? name : (std::filesystem::path(options.folder) / name).string();
        std::string why;
        result.environment = read_environment_exr(path, why);
        if (!result.environment) {
            diag.error(fmt::format("scene.environment.image: cannot use '{}': {}", path, why), "/scene/environment/image");
            return std::nullopt;
        }
    }
    m.precision = ir->scene.double_precision ? "double" : "float";
    if (const auto d = ir->outputs.find("distance"); d != ir->outputs.end())
        m.animated = (d->second.kind == IrInput::Kind::Implicit && d->second.implicit == ImplicitSource::Time) ||
                     (d->second.kind == IrInput::Kind::Node && ir->nodes[static_cast<std::size_t>(d->second.node)].time_dependent);
    {
        std::vector<ValueType> types;
        for (const auto& p : ir->params) types.push_back(p.type == ValueType::Bool ? ValueType::Int : p.type);
        auto offsets = std140_offsets(types, m.params_size);
        for (std::size_t i = 0; i < ir->params.size(); ++i) {
            const auto& p = ir->params[i];
            m.params.push_back({p.name, p.type, p.value, p.min, p.max, offsets[i], p.doc});
        }
        if (ir->params.empty()) m.params_size = 0;
    }

    // Code generation and the SPIR-V toolchain, pass by pass.
    SceneCodegen scene(*ir, library);
    // Passes are independent: compile them on all cores (glslang and SPIRV-Tools dominate the time),
    // one thread per core. More threads than cores only take turns, and each grows its own malloc
    // arena (page faults) instead of reusing the memory of the pass its thread compiled before.
    std::vector<const PassTemplate*> templates;
    auto wanted = [&](const std::string& name) {
        return options.only_passes.empty() ||
               std::find(options.only_passes.begin(), options.only_passes.end(), name) != options.only_passes.end();
    };
    for (const auto& tmpl : pass_templates())
        if (tmpl.runs_with(effects) && wanted(tmpl.name)) templates.push_back(&tmpl);
    std::vector<PassBuild> builds(templates.size());
    {
        std::atomic<std::size_t> next{0};
        auto build_passes = [&] {
            for (std::size_t i; (i = next++) < templates.size();)
                builds[i] = build_pass(*templates[i], effects, scene, m.spec_constants, options);
        };
        const std::size_t threads = std::min<std::size_t>(templates.size(), std::max(1u, std::thread::hardware_concurrency()));
        std::vector<std::future<void>> jobs;
        for (std::size_t t = 1; t < threads; ++t) jobs.push_back(std::async(std::launch::async, build_passes));
        build_passes();   // this thread is one of them
        for (auto& j : jobs) j.get();
    }
    for (auto& b : builds) {
        diag.append(b.diag);
        result.times.codegen_ms += b.times.codegen_ms;
        result.times.glslang_ms += b.times.glslang_ms;
        result.times.optimize_ms += b.times.optimize_ms;
        result.times.reflect_ms += b.times.reflect_ms;
        result.times.passes_compiled += b.times.passes_compiled;
        if (!b.reflection) continue;
        const PassReflection& refl = *b.reflection;
        ManifestPass mp;
        mp.name = b.pass.source.name;
        mp.local_size = refl.local_size;
        mp.bindings = refl.bindings;
        mp.push_constant_size = refl.push_constant_size;
        for (std::uint32_t id : refl.spec_constants)
            (is_dispatch_constant(id) ? mp.dispatch_constants : mp.spec_constants).push_back(id);
        for (const auto& [block, layout] : refl.uniform_blocks) m.uniform_blocks[block] = layout.size;
        if (auto it = refl.uniform_blocks.find("FgParams"); it != refl.uniform_blocks.end()) {
            // Reflection and our own std140 layout must agree, or the runtime would write wrong bytes.
            for (const auto& p : m.params) {
                auto off = it->second.offsets.find(p.name);
                if (off == it->second.offsets.end() || off->second != p.offset || it->second.size > m.params_size)
                    diag.error(fmt::format("internal: reflected offset of parameter {} disagrees with std140", p.name));
            }
        }
        m.passes.push_back(mp);
        result.passes.push_back(std::move(b.pass));
    }
    result.times.wall_ms = total_clock.lap();
    if (diag.has_errors()) return std::nullopt;
    result.ir = std::move(*ir);
    return result;
}

std::vector<std::uint8_t> pack_bytes(const CompileResult& result) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(result.manifest)));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", result.graph_text));
    nlohmann::json maps = nlohmann::json::object();
    for (const auto& p : result.passes) maps[p.source.name] = p.source.source_map.to_json();
    w.add(std::make_unique<TextChunk>(kTagSourceMap, "", maps.dump()));
    for (const auto& p : result.passes) w.add(std::make_unique<SpirvChunk>(p.source.name, p.spirv));
    if (result.environment) w.add(std::make_unique<EnvironmentChunk>(*result.environment));
    if (result.include_glsl)
        for (const auto& p : result.passes) w.add(std::make_unique<TextChunk>(kTagGlsl, p.source.name, p.source.glsl));
    return w.bytes();
}

}  // namespace fg
