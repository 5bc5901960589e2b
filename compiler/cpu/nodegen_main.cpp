// fg_nodegen: writes the C++ file that compiles every node body as C++ (the CPU twin) and the
// table that calls each one with CpuValue arguments. Run by the build, not by users.
//   fg_nodegen OUTPUT.cpp NODES_DIR file.json file.glsl ...
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "graph/node_library.h"

namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string accessor(fg::ValueType t) {
    switch (t) {
        case fg::ValueType::Float: return "f()";
        case fg::ValueType::Int: return "i()";
        case fg::ValueType::Bool: return "b()";
        case fg::ValueType::Vec2: return "v2()";
        case fg::ValueType::Vec3: return "v3()";
        case fg::ValueType::Vec4: return "v4()";
    }
    return "f()";
}

std::string cpp_type(fg::ValueType t) {
    switch (t) {
        case fg::ValueType::Float: return "double";
        case fg::ValueType::Int: return "int";
        case fg::ValueType::Bool: return "bool";
        case fg::ValueType::Vec2: return "glm::dvec2";
        case fg::ValueType::Vec3: return "glm::dvec3";
        case fg::ValueType::Vec4: return "glm::dvec4";
    }
    return "double";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        fmt::print(stderr, "usage: fg_nodegen OUTPUT.cpp NODES_DIR FILES...\n");
        return 2;
    }
    std::string output = argv[1];
    std::string base = argv[2];
    std::vector<std::string> texts, paths;
    for (int i = 3; i < argc; ++i) {
        std::string path = argv[i];
        texts.push_back(read_file(path));
        paths.push_back(path.rfind(base + "/", 0) == 0 ? path.substr(base.size() + 1) : path);
    }
    std::vector<fg::EmbeddedFile> files;
    for (std::size_t i = 0; i < texts.size(); ++i) files.push_back({paths[i], texts[i]});
    fg::Diagnostics diag;
    auto lib = fg::NodeLibrary::from_files(files, diag);
    if (diag.has_errors()) {
        fmt::print(stderr, "{}", diag.format());
        return 1;
    }

    std::string bodies, wrappers, entries;
    for (const auto* def : lib.all()) {
        if (!def->has_glsl_body()) continue;
        std::vector<std::optional<fg::ValueType>> instances;
        if (def->generic.empty()) instances.push_back(std::nullopt);
        for (auto t : def->generic) instances.push_back(t);
        for (const auto& inst : instances) {
            if (inst) bodies += fmt::format("#define T {}\n", fg::type_name(*inst));
            bodies += fmt::format("#include \"{}\"\n", def->glsl_path);
            if (inst) bodies += "#undef T\n";

            auto concrete = [&](const fg::PortType& p) { return p.concrete ? *p.concrete : *inst; };
            std::string name = def->function_name() + (inst ? "_" + std::string(fg::type_name(*inst)) : "");
            std::string call, locals, stores;
            for (std::size_t i = 0; i < def->inputs.size(); ++i)
                call += fmt::format("{}in[{}].{}", i ? ", " : "", i, accessor(concrete(def->inputs[i].type)));
            for (std::size_t i = 0; i < def->outputs.size(); ++i) {
                locals += fmt::format("    {} o{}{{}};\n", cpp_type(concrete(def->outputs[i].type)), i);
                call += fmt::format("{}o{}", call.empty() ? "" : ", ", i);
                stores += fmt::format("    out[{}] = CpuValue::of(o{});\n", i, i);
            }
            wrappers += fmt::format("void w_{}(const CpuValue* in, CpuValue* out) {{\n{}    glsl::{}({});\n{}}}\n", name,
                                    locals, def->function_name(), call, stores);
            wrappers += "\n";
            std::string tangent = "nullptr";
            if (!def->tangent.empty()) {
                // inputs, the rule's input tangents, then its output tangents: as the GLSL signature.
                std::string targs, tlocals, tstores;
                for (std::size_t i = 0; i < def->inputs.size(); ++i)
                    targs += fmt::format("{}in[{}].{}", i ? ", " : "", i, accessor(concrete(def->inputs[i].type)));
                for (std::size_t k = 0; k < def->tangent.inputs.size(); ++k)
                    targs += fmt::format("{}d_in[{}].{}", targs.empty() ? "" : ", ", k,
                                         accessor(concrete(def->find_input(def->tangent.inputs[k])->type)));
                for (std::size_t k = 0; k < def->tangent.outputs.size(); ++k) {
                    tlocals += fmt::format("    {} d{}{{}};\n",
                                           cpp_type(concrete(def->find_output(def->tangent.outputs[k])->type)), k);
                    targs += fmt::format(", d{}", k);
                    tstores += fmt::format("    d_out[{}] = CpuValue::of(d{});\n", k, k);
                }
                wrappers += fmt::format("void t_{}(const CpuValue* in, const CpuValue* d_in, CpuValue* d_out) {{\n{}    "
                                        "glsl::{}({});\n{}}}\n\n",
                                        name, tlocals, def->tangent_function_name(), targs, tstores);
                tangent = "&t_" + name;
            }
            entries += fmt::format("    {{\"{}\", {}, &w_{}, {}}},\n", def->type,
                                   inst ? fmt::format("ValueType::{}", [&] {
                                       std::string s(fg::type_name(*inst));
                                       s[0] = static_cast<char>(std::toupper(s[0]));
                                       return s;
                                   }())
                                        : "std::nullopt",
                                   name, tangent);
        }
    }

    std::string out = fmt::format(R"(// Generated by fg_nodegen from nodes/. Do not edit.
#include "cpu/cpu_glsl.h"
#include "cpu/cpu_node_registry.h"

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wshadow"
#endif

namespace fg::glsl {{
#define float double
#include "prelude.glsl"
#include "jacobian.glsl"
{}#undef float
}}  // namespace fg::glsl

namespace fg {{
namespace {{
{}const CpuNodeEntry kEntries[] = {{
{}}};
}}  // namespace

std::span<const CpuNodeEntry> cpu_node_entries() {{ return kEntries; }}
}}  // namespace fg
)",
                                  bodies, wrappers, entries);
    std::ifstream existing(output, std::ios::binary);
    std::stringstream ss;
    ss << existing.rdbuf();
    if (ss.str() != out) std::ofstream(output, std::ios::binary) << out;
    return 0;
}
