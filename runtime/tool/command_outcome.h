#pragma once
// What every `fgplay render` path does with its failures, in one place: a pack that does not read
// is reported with its diagnostics (the byte it broke at); a Vulkan error or any other exception
// becomes one line on stderr; validation errors, when the layer is on, fail the run. Exit code 1.
#include <functional>
#include <optional>
#include <string>

#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::fgplay {

std::optional<Pack> read_pack_or_report(const std::string& path);

// Runs `body`, turning exceptions into a message and exit code 1.
int run_reporting_errors(const std::function<int()>& body);

// The Vulkan context every `fgplay render` path asks for: validation and device as given,
// timestamps optional (lavapipe and some drivers lack them; times are then left out), and the
// user's pipeline cache (vk/pipeline_cache_file.h).
vk::ContextOptions render_context_options(bool validation, const std::string& device);

// True (after saying so) if the validation layer reported errors.
bool validation_failed(const vk::Context& ctx);

}  // namespace fg::fgplay
