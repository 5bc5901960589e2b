// libFuzzer target: the whole compiler behind the loader, on valid but strange graphs.
//
// The input bytes are not the graph: they drive a generator that builds one from the node library
// (random nodes, wires between ports of matching types, now and then a mismatched or forward wire,
// literals inside and outside each port's range, parameters, double precision), so nearly every
// input reaches validation, the IR, constant folding by the CPU twin, GLSL, glslang, the SPIR-V
// optimiser, spirv-val, SPIRV-Cross and the pack writer. Then:
//   - nothing crashes, throws or trips a sanitizer;
//   - a refused graph has errors, each saying where it came from (a JSON pointer or a node), and
//     none of them is the compiler's own fault (GLSL it generated that glslang rejects, SPIR-V that
//     the optimiser or spirv-val rejects, reflection that fails);
//   - an accepted graph has no errors, and its pack reads back with the same passes.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>
#include <nlohmann/json.hpp>

#include "compiler.h"
#include "graph/node_library.h"
#include "pack/pack_reader.h"

namespace {

using nlohmann::json;

struct Wire {
    std::string ref;    // "n3.distance"
    fg::ValueType type;
};

double number(FuzzedDataProvider& in, const fg::PortDefinition& port) {
    const double lo = port.min.value_or(-4.0), hi = port.max.value_or(4.0);
    switch (in.ConsumeIntegralInRange(0, 9)) {
        case 0: return lo - 1.0 - in.ConsumeFloatingPointInRange(0.0, 1e3);                   // below the range
        case 1: return hi + 1.0 + in.ConsumeFloatingPointInRange(0.0, 1e3);                   // above it
        case 2: return in.PickValueInArray({0.0, -0.0, 1e-30, -1e30, 1e30, 3.4e38, -3.4e38});  // extremes
        default: return lo + (hi - lo) * in.ConsumeProbability<double>();
    }
}

json literal(FuzzedDataProvider& in, const fg::PortDefinition& port, fg::ValueType type) {
    if (type == fg::ValueType::Bool) return in.ConsumeBool();
    if (type == fg::ValueType::Int) return static_cast<long long>(std::clamp(number(in, port), -1e15, 1e15));
    const int n = fg::component_count(type);
    if (n == 1 || in.ConsumeIntegralInRange(0, 4) == 0) return number(in, port);   // a number broadcasts
    json v = json::array();
    for (int i = 0; i < n; ++i) v.push_back(number(in, port));
    return v;
}

const Wire* pick_wire(FuzzedDataProvider& in, const std::vector<Wire>& wires, fg::ValueType type, bool any_type) {
    std::vector<const Wire*> fitting;
    for (const auto& w : wires)
        if (any_type || w.type == type || (w.type == fg::ValueType::Int && type == fg::ValueType::Float)) fitting.push_back(&w);
    if (fitting.empty()) return nullptr;
    return fitting[in.ConsumeIntegralInRange<std::size_t>(0, fitting.size() - 1)];
}

json make_graph(FuzzedDataProvider& in, const fg::NodeLibrary& library) {
    const auto defs = library.all();
    json g = {{"format", "fractograph-graph"}, {"version", 1}, {"name", "fuzzed"}};
    json params = json::object();
    std::vector<Wire> wires;
    const int param_count = in.ConsumeIntegralInRange(0, 2);
    for (int i = 0; i < param_count; ++i) {
        const double lo = in.ConsumeFloatingPointInRange(-10.0, 10.0), hi = lo + in.ConsumeFloatingPointInRange(0.0, 10.0);
        params["p" + std::to_string(i)] = {{"type", "float"}, {"default", lo + (hi - lo) * in.ConsumeProbability<double>()},
                                           {"min", lo}, {"max", hi}};
    }
    if (param_count) g["params"] = params;

    json nodes = json::array();
    const int count = in.ConsumeIntegralInRange(1, 7);
    for (int i = 0; i < count; ++i) {
        const fg::NodeDefinition& def = *defs[in.ConsumeIntegralInRange<std::size_t>(0, defs.size() - 1)];
        const std::string id = "n" + std::to_string(i);
        json node = {{"id", id}, {"type", def.type}, {"inputs", json::object()}};
        const fg::ValueType generic = def.generic.empty()
                                          ? fg::ValueType::Float
                                          : def.generic[in.ConsumeIntegralInRange<std::size_t>(0, def.generic.size() - 1)];
        for (const auto& port : def.inputs) {
            const fg::ValueType type = port.type.concrete.value_or(generic);
            switch (in.ConsumeIntegralInRange(0, 9)) {
                case 0: case 1: case 2: break;   // unbound: its default
                case 3: case 4: case 5: case 6: {
                    const bool any_type = in.ConsumeIntegralInRange(0, 15) == 0;   // now and then a type mismatch
                    if (const Wire* w = pick_wire(in, wires, type, any_type)) node["inputs"][port.name] = w->ref;
                    break;
                }
                case 7:
                    if (param_count && type == fg::ValueType::Float)
                        node["inputs"][port.name] = "$p" + std::to_string(in.ConsumeIntegralInRange(0, param_count - 1));
                    break;
                case 8:
                    if (in.ConsumeIntegralInRange(0, 7) == 0)   // a wire to a later node: maybe a cycle
                        node["inputs"][port.name] = "n" + std::to_string(in.ConsumeIntegralInRange(0, count));
                    break;
                default: node["inputs"][port.name] = literal(in, port, type); break;
            }
        }
        for (const auto& port : def.outputs) wires.push_back({id + "." + port.name, port.type.concrete.value_or(generic)});
        nodes.push_back(node);
    }
    g["nodes"] = nodes;

    json outputs = json::object();
    const struct {
        const char* name;
        fg::ValueType type;
    } kOutputs[] = {{"distance", fg::ValueType::Float}, {"albedo", fg::ValueType::Vec3}, {"diffuse", fg::ValueType::Float},
                    {"ao", fg::ValueType::Float},       {"emission", fg::ValueType::Vec3}};
    for (const auto& o : kOutputs)
        if (std::string(o.name) == "distance" || in.ConsumeBool())
            if (const Wire* w = pick_wire(in, wires, o.type, in.ConsumeIntegralInRange(0, 15) == 0)) outputs[o.name] = w->ref;
    g["outputs"] = outputs;

    json scene = json::object();
    if (in.ConsumeIntegralInRange(0, 3) == 0) scene["precision"] = "double";
    if (in.ConsumeIntegralInRange(0, 3) == 0) scene["bounds"] = {{"radius", in.ConsumeFloatingPointInRange(0.001, 1e6)}};
    if (in.ConsumeIntegralInRange(0, 3) == 0)
        scene["camera"] = {{"position", {in.ConsumeFloatingPointInRange(-1e6, 1e6), 0.5, 3.0}}, {"target", {0.0, 0.0, 0.0}}};
    if (!scene.empty()) g["scene"] = scene;
    return g;
}

// Errors that are the compiler's fault, not the graph's.
bool compiler_fault(const fg::Diagnostic& d) {
    for (const char* prefix : {"GLSL error", "GLSL link error", "SPIR-V optimisation failed", "spirv-val rejected", "SPIRV-Cross",
                               "internal"})
        if (d.message.rfind(prefix, 0) == 0) return true;
    return false;
}

[[noreturn]] void fail(const char* what, const json& graph, const fg::Diagnostics& diag) {
    std::fprintf(stderr, "%s\ngraph:\n%s\ndiagnostics:\n%s\n", what, graph.dump(2).c_str(), diag.format().c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    const fg::NodeLibrary& library = fg::NodeLibrary::builtin();
    const json graph = make_graph(in, library);
    const std::string text = graph.dump();
    fg::Diagnostics diag;
    try {
        // A scene may name an environment image: only inside the working folder, as the studio
        // allows, so that no input makes the fuzzer read a device or another file system.
        fg::CompileOptions options;
        options.folder_confined = true;
        auto result = fg::compile_graph(text, library, options, diag);
        if (!result) {
            if (!diag.has_errors()) fail("compile_graph refused the graph without an error", graph, diag);
            for (const auto& d : diag.items()) {
                if (d.severity != fg::Severity::Error) continue;
                if (compiler_fault(d)) fail("the compiler refused code it generated itself", graph, diag);
                if (d.pointer.empty() && d.node_id.empty()) fail("an error that does not say where it came from", graph, diag);
            }
            return 0;
        }
        if (diag.has_errors()) fail("compile_graph accepted the graph but reported errors", graph, diag);
        const std::vector<std::uint8_t> bytes = fg::pack_bytes(*result);
        fg::Diagnostics read_diag;
        auto pack = fg::read_pack(bytes, read_diag);
        if (!pack || read_diag.has_errors()) fail("the written pack does not read back", graph, read_diag);
        if (pack->manifest.passes.size() != result->manifest.passes.size())
            fail("the pack read back has other passes than were written", graph, read_diag);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "the compiler threw: %s\ngraph:\n%s\n", e.what(), graph.dump(2).c_str());
        std::abort();
    }
    return 0;
}
