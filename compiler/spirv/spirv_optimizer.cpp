#include "spirv_optimizer.h"

#include <fmt/format.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace fg {

namespace {
constexpr spv_target_env kEnv = SPV_ENV_VULKAN_1_2;
}

std::optional<std::vector<std::uint32_t>> optimize_spirv(const std::string& pass, const std::vector<std::uint32_t>& in,
                                                         Diagnostics& diag) {
    spvtools::Optimizer opt(kEnv);
    std::string messages;
    opt.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t& pos, const char* m) {
        if (level <= SPV_MSG_ERROR) messages += fmt::format("{} (word {})\n", m, pos.index);
    });
    opt.RegisterPerformancePasses();
    std::vector<std::uint32_t> out;
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);  // validated on its own below, with a clearer message
    if (!opt.Run(in.data(), in.size(), &out, options)) {
        diag.error(fmt::format("SPIR-V optimisation failed (pass {}): {}", pass, messages));
        return std::nullopt;
    }
    return out;
}

bool validate_spirv(const std::string& pass, const std::vector<std::uint32_t>& words, Diagnostics& diag) {
    spvtools::SpirvTools tools(kEnv);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t& pos, const char* m) {
        if (level <= SPV_MSG_ERROR) messages += fmt::format("{} (word {})\n", m, pos.index);
    });
    if (!tools.Validate(words)) {
        diag.error(fmt::format("spirv-val rejected pass {}: {}", pass, messages));
        return false;
    }
    return true;
}

std::string disassemble_spirv(const std::vector<std::uint32_t>& words) {
    spvtools::SpirvTools tools(kEnv);
    std::string text;
    tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT);
    return text;
}

}  // namespace fg
