#include "spirv/pass_cache_file.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <system_error>

#include <elf.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glslang/build_info.h>
#include <link.h>
#include <spirv-tools/libspirv.h>
#include <xxhash.h>

#include "common/diagnostics.h"
#include "common/user_cache_folder.h"
#include "compiler.h"
#include "pack/pack_writer.h"

namespace fg {

namespace {

constexpr char kMagic[8] = {'F', 'G', 'P', 'A', 'S', 'S', '\r', '\n'};
constexpr std::uint32_t kFormat = 1;
constexpr std::uint32_t kMaxWords = 1u << 24;   // 64 MiB: more is a damaged header, not a pass

struct PassFileHeader {
    char magic[8];
    std::uint32_t format;
    std::uint32_t words;      // SPIR-V words after the header
    std::uint64_t key;        // the file's name again: a file renamed by hand is not trusted
    std::uint64_t checksum;   // XXH64 of the words
};
static_assert(sizeof(PassFileHeader) == 32);

// The first object dl_iterate_phdr reports is the executable; its PT_NOTE segments hold the build
// id the linker wrote (--build-id, on by default in Debian's gcc).
std::string executable_build_id() {
    std::string id;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* out) {
            for (int i = 0; i < info->dlpi_phnum; ++i) {
                const ElfW(Phdr)& segment = info->dlpi_phdr[i];
                if (segment.p_type != PT_NOTE) continue;
                const std::size_t align = segment.p_align > 4 ? segment.p_align : 4;
                auto padded = [align](std::size_t n) { return (n + align - 1) / align * align; };
                const auto* at = reinterpret_cast<const unsigned char*>(info->dlpi_addr + segment.p_vaddr);
                const auto* end = at + segment.p_memsz;
                while (at + sizeof(ElfW(Nhdr)) <= end) {
                    ElfW(Nhdr) note;
                    std::memcpy(&note, at, sizeof(note));
                    const unsigned char* name = at + sizeof(note);
                    const unsigned char* desc = name + padded(note.n_namesz);
                    if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0 &&
                        desc + note.n_descsz <= end) {
                        *static_cast<std::string*>(out) =
                            fmt::format("{:02x}", fmt::join(std::span(desc, note.n_descsz), ""));
                        return 1;
                    }
                    at = desc + padded(note.n_descsz);
                }
            }
            return 1;
        },
        &id);
    return id;
}

}  // namespace

std::filesystem::path user_pass_cache_folder() { return user_cache_folder("FG_PASS_CACHE", "passes"); }

const std::string& toolchain_id() {
    static const std::string id = [] {
        const std::string build = executable_build_id();
        if (build.empty()) return std::string();
        return fmt::format("fgc {}; glslang {}.{}.{}{}; {}; build {}", kCompilerVersion, GLSLANG_VERSION_MAJOR,
                           GLSLANG_VERSION_MINOR, GLSLANG_VERSION_PATCH, GLSLANG_VERSION_FLAVOR,
                           spvSoftwareVersionDetailsString(), build);
    }();
    return id;
}

std::filesystem::path pass_file(const std::filesystem::path& folder, std::uint64_t key) {
    return folder / fmt::format("{:016x}.spv", key);
}

std::optional<std::vector<std::uint32_t>> read_pass_file(const std::filesystem::path& file, std::uint64_t key) {
    std::ifstream in(file, std::ios::binary);
    PassFileHeader header;
    if (!in.read(reinterpret_cast<char*>(&header), sizeof(header))) return std::nullopt;
    if (std::memcmp(header.magic, kMagic, sizeof(kMagic)) != 0 || header.format != kFormat || header.key != key ||
        header.words == 0 || header.words > kMaxWords)
        return std::nullopt;
    std::vector<std::uint32_t> words(header.words);
    const auto bytes = static_cast<std::streamsize>(words.size() * sizeof(std::uint32_t));
    if (!in.read(reinterpret_cast<char*>(words.data()), bytes)) return std::nullopt;
    if (in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;   // longer than its header says
    if (XXH64(words.data(), static_cast<std::size_t>(bytes), 0) != header.checksum) return std::nullopt;
    return words;
}

bool write_pass_file(const std::filesystem::path& file, std::uint64_t key, std::span<const std::uint32_t> spirv) {
    PassFileHeader header{};
    std::memcpy(header.magic, kMagic, sizeof(kMagic));
    header.format = kFormat;
    header.words = static_cast<std::uint32_t>(spirv.size());
    header.key = key;
    header.checksum = XXH64(spirv.data(), spirv.size_bytes(), 0);
    std::vector<std::uint8_t> bytes(sizeof(header) + spirv.size_bytes());
    std::memcpy(bytes.data(), &header, sizeof(header));
    std::memcpy(bytes.data() + sizeof(header), spirv.data(), spirv.size_bytes());
    std::error_code error;
    std::filesystem::create_directories(file.parent_path(), error);
    Diagnostics ignored;   // the cache is a hint: a pass it cannot keep is compiled again next time
    return write_file_atomically(file.string(), bytes, ignored);
}

void trim_pass_folder(const std::filesystem::path& folder, std::uintmax_t max_bytes) {
    struct File {
        std::filesystem::file_time_type time;
        std::uintmax_t size;
        std::filesystem::path path;
    };
    std::vector<File> files;
    std::uintmax_t total = 0;
    std::error_code error;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        // Another process may remove a file meanwhile; a folder has no file size.
        std::error_code no_time, no_size;
        File f{it->last_write_time(no_time), it->file_size(no_size), it->path()};
        if (no_time || no_size) continue;
        total += f.size;
        files.push_back(std::move(f));
    }
    std::sort(files.begin(), files.end(), [](const File& a, const File& b) { return a.time < b.time; });
    for (const auto& f : files) {
        if (total <= max_bytes) break;
        if (std::filesystem::remove(f.path, error)) total -= f.size;
    }
}

}  // namespace fg
