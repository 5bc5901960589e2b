#include "glsl_compiler.h"

#include <fmt/format.h>
#include <mutex>
#include <regex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace fg {

namespace {

void init_glslang() {
    static std::once_flag once;
    std::call_once(once, [] {
        glslang::InitializeProcess();
        std::atexit([] { glslang::FinalizeProcess(); });
    });
}

std::string line_of(const std::string& text, int line) {
    std::istringstream in(text);
    std::string l;
    for (int i = 1; std::getline(in, l); ++i)
        if (i == line) return l;
    return {};
}

}  // namespace

std::optional<Diagnostic> map_glslang_message(const std::string& log_line, const std::string& pass,
                                              const std::string& glsl, const SourceMap& map) {
    static const std::regex re(R"(^(ERROR|WARNING): (?:[^:]*):(\d+): (.*)$)");
    std::smatch m;
    if (!std::regex_match(log_line, m, re)) return std::nullopt;
    Diagnostic d;
    d.severity = m[1] == "ERROR" ? Severity::Error : Severity::Warning;
    int line = std::stoi(m[2]);
    std::string message = m[3];
    auto origin = map.lookup(line);
    std::string where;
    if (origin) {
        switch (origin->kind) {
            case SourceOrigin::Kind::Node:
                d.node_id = origin->node_id;
                d.pointer = origin->pointer;
                where = origin->line ? fmt::format("in the node's code, line {}: ", origin->line) : "";
                break;
            case SourceOrigin::Kind::Library:
            case SourceOrigin::Kind::Template:
                where = fmt::format("{}:{}: ", origin->file, origin->line);
                break;
            case SourceOrigin::Kind::Generated: break;
        }
    }
    d.message = fmt::format("GLSL {} (pass {}): {}{}", d.severity == Severity::Error ? "error" : "warning", pass,
                            where, message);
    d.context = fmt::format("{:5} | {}", line, line_of(glsl, line));
    return d;
}

std::optional<std::vector<std::uint32_t>> compile_glsl(const std::string& pass, const std::string& glsl,
                                                       const SourceMap& map, Diagnostics& diag) {
    init_glslang();
    glslang::TShader shader(EShLangCompute);
    const char* text = glsl.c_str();
    const char* name = pass.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
    // GLSL leaves min/max/clamp with NaN undefined; ask for the NaN-safe forms.
    shader.setNanMinMaxClamp(true);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    bool ok = shader.parse(GetDefaultResources(), 460, false, messages);
    auto report = [&](const char* log) {
        std::istringstream in(log);
        std::string l;
        bool any = false;
        while (std::getline(in, l)) {
            if (auto d = map_glslang_message(l, pass, glsl, map)) {
                diag.add(*d);
                any = any || d->severity == Severity::Error;
            }
        }
        return any;
    };
    if (!ok) {
        if (!report(shader.getInfoLog())) diag.error(fmt::format("GLSL error (pass {}): {}", pass, shader.getInfoLog()));
        return std::nullopt;
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        diag.error(fmt::format("GLSL link error (pass {}): {}", pass, program.getInfoLog()));
        return std::nullopt;
    }
    std::vector<unsigned int> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;
    options.disableOptimizer = true;  // glslang 12 does not optimise; SPIRV-Tools does (spirv_optimizer.h)
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger, &options);
    std::string log = logger.getAllMessages();
    if (!log.empty()) diag.warning(fmt::format("SPIR-V generation (pass {}): {}", pass, log));
    return std::vector<std::uint32_t>(spirv.begin(), spirv.end());
}

}  // namespace fg
