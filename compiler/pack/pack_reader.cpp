#include "pack_reader.h"

#include <fmt/format.h>
#include <fstream>
#include <set>
#include <xxhash.h>

#include "graph/json_text.h"
#include "pack_format.h"

namespace fg {

namespace {

using namespace pack_format;

std::uint64_t get(std::span<const std::uint8_t> b, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(b[at + static_cast<std::size_t>(i)]) << (8 * i);
    return v;
}

bool printable_tag(const ChunkTag& t) {
    for (char c : t)
        if (c < 'A' || c > 'Z') return false;
    return true;
}

std::string tag_for_message(const ChunkTag& t) {
    if (printable_tag(t)) return tag_text(t);
    return fmt::format("0x{:02x}{:02x}{:02x}{:02x}", static_cast<unsigned char>(t[0]), static_cast<unsigned char>(t[1]),
                       static_cast<unsigned char>(t[2]), static_cast<unsigned char>(t[3]));
}

class PackParser {
public:
    PackParser(std::span<const std::uint8_t> bytes, Diagnostics& diag) : b_(bytes), diag_(diag) {}

    std::optional<Pack> parse() {
        if (!parse_header()) return std::nullopt;
        std::size_t at = kHeaderSize;
        std::vector<std::pair<PackChunkInfo, std::span<const std::uint8_t>>> chunks;
        for (std::uint32_t i = 0; i < count_; ++i) {
            auto chunk = parse_chunk(at, i);
            if (!chunk) return std::nullopt;
            chunks.push_back(*chunk);
        }
        if (at != b_.size()) {
            fail(at, fmt::format("{} bytes follow the last chunk", b_.size() - at));
            return std::nullopt;
        }
        return assemble(chunks);
    }

private:
    std::span<const std::uint8_t> b_;
    Diagnostics& diag_;
    Pack pack_;
    std::uint32_t count_ = 0;

    void fail(std::uint64_t offset, std::string message) {
        Diagnostic d;
        d.message = std::move(message);
        d.byte = offset;
        diag_.add(d);
    }

    bool parse_header() {
        if (b_.size() < 4 || !std::equal(kPackMagic.begin(), kPackMagic.end(), b_.begin())) {
            fail(0, "not a Fractograph pack: the file does not start with \"FGPK\"");
            return false;
        }
        if (b_.size() < kHeaderSize) {
            fail(b_.size(), fmt::format("truncated: {} bytes, the header alone is {}", b_.size(), kHeaderSize));
            return false;
        }
        std::uint64_t stored = get(b_, 24, 8);
        std::uint64_t computed = XXH64(b_.data(), 24, kSeed);
        if (stored != computed) {
            fail(24, fmt::format("header checksum mismatch (stored {:016x}, computed {:016x}): the file is damaged",
                                 stored, computed));
            return false;
        }
        pack_.version_major = static_cast<std::uint16_t>(get(b_, 4, 2));
        pack_.version_minor = static_cast<std::uint16_t>(get(b_, 6, 2));
        if (pack_.version_major > kPackVersionMajor) {
            fail(4, fmt::format("pack format {}.{} is newer than this build reads ({}.x); update Fractograph",
                                pack_.version_major, pack_.version_minor, kPackVersionMajor));
            return false;
        }
        if (pack_.version_major == 0) {
            fail(4, "pack format version 0 does not exist");
            return false;
        }
        count_ = static_cast<std::uint32_t>(get(b_, 8, 4));
        if (count_ > kMaxChunks) {
            fail(8, fmt::format("{} chunks is more than the {} a pack may hold", count_, kMaxChunks));
            return false;
        }
        if (get(b_, 12, 4) != 0) {
            fail(12, "reserved header field is not zero");
            return false;
        }
        pack_.file_size = get(b_, 16, 8);
        if (pack_.file_size != b_.size()) {
            fail(16, fmt::format("the header says the pack is {} bytes, the file has {}: {}", pack_.file_size, b_.size(),
                                 pack_.file_size > b_.size() ? "truncated" : "extra bytes at the end"));
            return false;
        }
        return true;
    }

    std::optional<std::pair<PackChunkInfo, std::span<const std::uint8_t>>> parse_chunk(std::size_t& at,
                                                                                         std::uint32_t index) {
        PackChunkInfo info;
        info.offset = at;
        if (b_.size() - at < kChunkHeaderSize) {
            fail(at, fmt::format("truncated: chunk {} of {} starts {} bytes before the end", index + 1, count_,
                                 b_.size() - at));
            return std::nullopt;
        }
        std::copy_n(b_.begin() + static_cast<std::ptrdiff_t>(at), 4, info.tag.begin());
        std::uint64_t name_len = get(b_, at + 4, 4);
        info.payload_size = get(b_, at + 8, 8);
        std::string what = fmt::format("chunk {} ('{}')", index + 1, tag_for_message(info.tag));
        if (name_len > kMaxNameLength) {
            fail(at + 4, fmt::format("{}: name length {} exceeds {}", what, name_len, kMaxNameLength));
            return std::nullopt;
        }
        if (info.payload_size > kMaxPayload) {
            fail(at + 8, fmt::format("{}: payload size {} exceeds {}", what, info.payload_size, kMaxPayload));
            return std::nullopt;
        }
        std::uint64_t total = kChunkHeaderSize + name_len + info.payload_size + kChecksumSize;
        if (total > b_.size() - at) {
            fail(at, fmt::format("truncated: {} needs {} bytes, {} remain", what, total, b_.size() - at));
            return std::nullopt;
        }
        std::size_t body = at + kChunkHeaderSize;
        info.name.assign(reinterpret_cast<const char*>(b_.data() + body), static_cast<std::size_t>(name_len));
        std::size_t checksum_at = static_cast<std::size_t>(at + total - kChecksumSize);
        info.checksum = get(b_, checksum_at, 8);
        std::uint64_t computed = XXH64(b_.data() + at, checksum_at - at, kSeed);
        if (info.checksum != computed) {
            fail(checksum_at, fmt::format("{}{}: checksum mismatch (stored {:016x}, computed {:016x}): the chunk is "
                                          "damaged or was edited",
                                          what, info.name.empty() ? "" : " " + info.name, info.checksum, computed));
            return std::nullopt;
        }
        if (!printable_tag(info.tag)) {
            fail(at, fmt::format("{}: the tag is not four capital letters", what));
            return std::nullopt;
        }
        auto payload = b_.subspan(body + static_cast<std::size_t>(name_len), static_cast<std::size_t>(info.payload_size));
        at += static_cast<std::size_t>(total);
        pack_.chunks.push_back(info);
        return std::make_pair(info, payload);
    }

    std::optional<Pack> assemble(const std::vector<std::pair<PackChunkInfo, std::span<const std::uint8_t>>>& chunks) {
        std::set<std::pair<std::string, std::string>> seen;
        const PackChunkInfo* manifest_chunk = nullptr;
        std::span<const std::uint8_t> manifest_bytes;
        bool have_graph = false;
        for (const auto& [info, payload] : chunks) {
            std::string tag = tag_text(info.tag);
            bool unique_kind = info.tag == kTagManifest || info.tag == kTagGraph || info.tag == kTagSourceMap ||
                               info.tag == kTagEnvironment;
            if (unique_kind && !info.name.empty()) {
                fail(info.offset, fmt::format("chunk '{}' has a name ('{}'); a pack has one unnamed {} chunk", tag,
                                              info.name, tag));
                return std::nullopt;
            }
            if (!seen.insert({tag, info.name}).second) {
                fail(info.offset, fmt::format("chunk '{}' {} appears twice", tag, info.name));
                return std::nullopt;
            }
            std::string text(reinterpret_cast<const char*>(payload.data()), payload.size());
            if (info.tag == kTagManifest) {
                manifest_chunk = &info;
                manifest_bytes = payload;
            } else if (info.tag == kTagSpirv) {
                if (payload.size() % 4 != 0 || payload.size() < 20 || get(payload, 0, 4) != 0x07230203u) {
                    fail(info.offset, fmt::format("SPIR-V chunk '{}' does not hold a SPIR-V module", info.name));
                    return std::nullopt;
                }
                std::vector<std::uint32_t> words(payload.size() / 4);
                for (std::size_t w = 0; w < words.size(); ++w) words[w] = static_cast<std::uint32_t>(get(payload, w * 4, 4));
                pack_.spirv[info.name] = std::move(words);
            } else if (info.tag == kTagGraph) {
                pack_.graph = text;
                have_graph = true;
            } else if (info.tag == kTagSourceMap) {
                Diagnostics json_diag;
                auto map = parse_json_text(text, json_diag);
                if (!map || !map->is_object()) {
                    fail(info.offset, "the source map chunk is not a JSON object");
                    return std::nullopt;
                }
                pack_.source_map = std::move(*map);
            } else if (info.tag == kTagGlsl) {
                pack_.glsl[info.name] = text;
            } else if (info.tag == kTagEnvironment) {
                std::string why;
                pack_.environment = environment_from_payload(payload, why);
                if (!pack_.environment) {
                    fail(info.offset, why);
                    return std::nullopt;
                }
            } else if (pack_.version_minor <= kPackVersionMinor) {
                fail(info.offset, fmt::format("unknown chunk tag '{}' in a {}.{} pack", tag, pack_.version_major,
                                              pack_.version_minor));
                return std::nullopt;
            }  // newer minor version: an added chunk kind this build does not need
        }
        if (!manifest_chunk) {
            fail(kHeaderSize, "the pack has no manifest chunk (MANI)");
            return std::nullopt;
        }
        if (!have_graph) {
            fail(kHeaderSize, "the pack has no source graph chunk (GRPH)");
            return std::nullopt;
        }
        {
            Diagnostics json_diag;
            auto parsed = parse_json_text(
                std::string_view(reinterpret_cast<const char*>(manifest_bytes.data()), manifest_bytes.size()), json_diag);
            if (!parsed) {
                std::string why = json_diag.items().empty() ? "" : ": " + json_diag.items().front().message;
                fail(manifest_chunk->offset, "the manifest chunk is not valid JSON" + why);
                return std::nullopt;
            }
            pack_.manifest_json = std::move(*parsed);
        }
        Diagnostics manifest_diag;
        auto m = manifest_from_json(pack_.manifest_json, manifest_diag);
        for (auto d : manifest_diag.items()) {
            d.byte = manifest_chunk->offset;
            diag_.add(d);
        }
        if (!m) return std::nullopt;
        pack_.manifest = *m;
        // Every pass the manifest lists has its SPIR-V, and every SPIR-V chunk belongs to a pass.
        bool consistent = true;
        for (const auto& p : pack_.manifest.passes)
            if (!pack_.spirv.count(p.name)) {
                fail(manifest_chunk->offset, fmt::format("manifest lists pass '{}' but the pack has no SPIR-V for it", p.name));
                consistent = false;
            }
        for (const auto& [name, _] : pack_.spirv)
            if (!pack_.manifest.find_pass(name)) {
                fail(manifest_chunk->offset, fmt::format("SPIR-V chunk '{}' belongs to no pass in the manifest", name));
                consistent = false;
            }
        for (const auto& [name, _] : pack_.glsl)
            if (!pack_.manifest.find_pass(name)) {
                fail(manifest_chunk->offset, fmt::format("GLSL chunk '{}' belongs to no pass in the manifest", name));
                consistent = false;
            }
        if (fmt::format("{:016x}", XXH64(pack_.graph.data(), pack_.graph.size(), 0)) != pack_.manifest.graph_hash) {
            fail(manifest_chunk->offset, "the manifest's graph hash does not match the source graph chunk");
            consistent = false;
        }
        const auto& env = pack_.manifest.scene.environment;
        if (env && !env->image.empty() && !pack_.environment) {
            fail(manifest_chunk->offset, fmt::format("the scene's environment is the image '{}', but the pack has no "
                                                     "environment chunk (ENVI)", env->image));
            consistent = false;
        }
        if (!consistent) return std::nullopt;
        return std::move(pack_);
    }
};

}  // namespace

std::optional<Pack> read_pack(std::span<const std::uint8_t> bytes, Diagnostics& diag) {
    return PackParser(bytes, diag).parse();
}

std::optional<Pack> read_pack_file(const std::string& path, Diagnostics& diag) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        diag.error(fmt::format("cannot open pack {}", path));
        return std::nullopt;
    }
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return read_pack(bytes, diag);
}

}  // namespace fg
