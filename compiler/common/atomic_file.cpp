#include "atomic_file.h"

#include <atomic>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace fg {

bool write_file_atomically(const std::string& path, std::span<const std::uint8_t> bytes, Diagnostics& diag) {
    static std::atomic<unsigned> calls{0};
    char host[64] = {};
    ::gethostname(host, sizeof host - 1);
    const std::string tmp = fmt::format("{}.tmp.{}.{}-{}", path, host, static_cast<long>(::getpid()), calls++);
    std::error_code ec;
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            diag.error(fmt::format("cannot write {}", tmp));
            return false;
        }
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out.flush()) {
            diag.error(fmt::format("writing {} failed (disk full?)", tmp));
            out.close();
            std::filesystem::remove(tmp, ec);
            return false;
        }
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        diag.error(fmt::format("cannot move {} to {}: {}", tmp, path, ec.message()));
        std::filesystem::remove(tmp, ec);
        return false;
    }
    return true;
}

}  // namespace fg
