#pragma once
// A test's own temporary folder: a fresh, uniquely named directory under the system's temporary
// directory ($TMPDIR, else /tmp), removed with everything in it when the test is done. Two runs
// of the suite on one machine, or two tests at once, never share a file.
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace fg::test {

class ScratchDir {
public:
    explicit ScratchDir(const std::string& prefix = "fg_test") {
        std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "_XXXXXX")).string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot make a temporary directory from " + pattern);
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
    std::filesystem::path path_;
};

}  // namespace fg::test
