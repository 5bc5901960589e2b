#include "vk/log.h"

#include <memory>

#include <spdlog/sinks/stdout_color_sinks.h>

namespace fg::vk {

spdlog::logger& logger() {
    // Kept out of spdlog's registry: another part of the program may already own a logger
    // named "vk", and registering twice throws.
    static const std::shared_ptr<spdlog::logger> logger = [] {
        auto sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
        auto made = std::make_shared<spdlog::logger>("fg.vk", std::move(sink));
        made->set_pattern("[%n] [%^%l%$] %v");
        return made;
    }();
    return *logger;
}

}  // namespace fg::vk
