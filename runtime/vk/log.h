#pragma once
// The Vulkan layer's own logger. It writes to stderr so tools that print results on stdout
// (pack dumps, benchmark tables) stay machine-readable while validation is on.
#include <spdlog/logger.h>

namespace fg::vk {

spdlog::logger& logger();

}  // namespace fg::vk
