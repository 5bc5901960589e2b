#pragma once
// Writing a whole file or none of it: through a temporary file beside it and a rename, so a reader
// (another process, or a task of a job array on another host sharing the folder) never sees half a
// file, and two writers of one file at once leave one of their files whole.
#include <cstdint>
#include <span>
#include <string>

#include "diagnostics.h"

namespace fg {

// The temporary's name is unique to this host, process and call. False, with the reason in
// `diag`, when the file could not be written; the temporary is then removed.
bool write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes, Diagnostics& diag);

}  // namespace fg
