#include "command_outcome.h"

#include <fmt/format.h>

#include "vk/pipeline_cache_file.h"
#include "vk/vulkan_error.h"

namespace fg::fgplay {

std::optional<Pack> read_pack_or_report(const std::string& path) {
    Diagnostics diag;
    auto pack = read_pack_file(path, diag);
    if (!pack) fmt::print(stderr, "{}", diag.format(path));
    return pack;
}

int run_reporting_errors(const std::function<int()>& body) {
    try {
        return body();
    } catch (const vk::VulkanError& e) {
        fmt::print(stderr, "fgplay: Vulkan: {}\n", e.what());
    } catch (const std::exception& e) {
        fmt::print(stderr, "fgplay: {}\n", e.what());
    }
    return 1;
}

vk::ContextOptions render_context_options(bool validation, const std::string& device) {
    vk::ContextOptions options;
    options.validation = validation;
    options.device = device;
    options.require_timestamps = false;
    options.shader_float64 = true;   // on where supported: packs of precision "double" need it
    options.pipeline_cache_file = vk::user_pipeline_cache_file();
    return options;
}

bool validation_failed(const vk::Context& ctx) {
    if (!ctx.validation_enabled() || ctx.validation_errors() == 0) return false;
    fmt::print(stderr, "{} Vulkan validation errors\n", ctx.validation_errors());
    return true;
}

}  // namespace fg::fgplay
