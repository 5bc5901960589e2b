// The .fgpack format (docs/pack-format.md): what the compiler writes reads back unchanged, and the
// reader refuses anything it cannot trust, naming the byte offset.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <xxhash.h>

#include "common/spec_constants.h"
#include "compiler.h"
#include "graph/node_library.h"
#include "pack/chunk_tags.h"
#include "pack/manifest.h"
#include "pack/pack_chunk.h"
#include "pack/pack_format.h"
#include "pack/pack_reader.h"
#include "pack/pack_writer.h"

namespace fg {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The gallery Mandelbulb, compiled once for the whole file (with and without the debug GLSL chunks).
const CompileResult& gallery(bool include_glsl = false) {
    static std::map<bool, CompileResult> cache;
    auto it = cache.find(include_glsl);
    if (it == cache.end()) {
        std::string text = read_text(std::string(FG_SOURCE_DIR) + "/graphs/gallery/mandelbulb.json");
        EXPECT_FALSE(text.empty()) << "cannot read the gallery graph";
        Diagnostics diag;
        CompileOptions options;
        options.include_glsl = include_glsl;
        auto result = compile_graph(text, NodeLibrary::builtin(), options, diag);
        EXPECT_TRUE(result.has_value()) << diag.format("mandelbulb.json");
        if (!result) {
            static CompileResult empty;
            return empty;
        }
        it = cache.emplace(include_glsl, std::move(*result)).first;
    }
    return it->second;
}

const Bytes& gallery_pack() {
    static const Bytes bytes = pack_bytes(gallery());
    return bytes;
}

std::uint64_t get_le(const Bytes& b, std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(b[at + static_cast<std::size_t>(i)]) << (8 * i);
    return v;
}
void put_le(Bytes& b, std::size_t at, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}
// Recomputes the header checksum (xxh64 of bytes 0..24, seed kSeed, little-endian at byte 24), so that
// a test of a header field reaches the check of that field rather than the checksum.
void reseal_header(Bytes& b) { put_le(b, 24, XXH64(b.data(), 24, pack_format::kSeed), 8); }
void set_version(Bytes& b, std::uint16_t major, std::uint16_t minor) {
    put_le(b, 4, major, 2);
    put_le(b, 6, minor, 2);
    reseal_header(b);
}

// The outcome of reading a pack that must be refused: the diagnostics, for the test to inspect.
struct Refusal {
    bool refused = false;
    Diagnostics diag;
    const Diagnostic* first_error() const {
        for (const auto& d : diag.items())
            if (d.severity == Severity::Error) return &d;
        return nullptr;
    }
    std::string text() const { return diag.format("test.fgpack"); }
};

Refusal read_expecting_refusal(const Bytes& bytes) {
    Refusal r;
    auto pack = read_pack(bytes, r.diag);
    r.refused = !pack.has_value();
    return r;
}

std::optional<Pack> read_ok(const Bytes& bytes) {
    Diagnostics diag;
    auto pack = read_pack(bytes, diag);
    EXPECT_TRUE(pack.has_value()) << diag.format("test.fgpack");
    EXPECT_FALSE(diag.has_errors()) << diag.format("test.fgpack");
    return pack;
}

// A diagnostic carrying this message fragment and this byte offset is among the errors.
::testing::AssertionResult has_error(const Refusal& r, const std::string& fragment,
                                     std::optional<std::uint64_t> byte = std::nullopt) {
    if (!r.refused) return ::testing::AssertionFailure() << "the pack was accepted";
    for (const auto& d : r.diag.items()) {
        if (d.severity != Severity::Error || d.message.find(fragment) == std::string::npos) continue;
        if (!d.byte) return ::testing::AssertionFailure() << "error without a byte offset: " << d.message;
        if (byte && *d.byte != *byte)
            return ::testing::AssertionFailure() << "error at byte " << *d.byte << ", expected " << *byte << ": "
                                                 << d.message;
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "no error mentions \"" << fragment << "\"; got:\n" << r.text();
}

// A tiny SPIR-V module: only the 5-word header (the reader checks magic and size, nothing more).
std::vector<std::uint32_t> tiny_spirv() { return {0x07230203u, 0x00010500u, 0u, 1u, 0u}; }

const std::string kTinyGraph = R"({"format": "fractograph-graph", "version": 1, "name": "tiny"})";

// A small, hand-made manifest: one pass "main" using knob 1, no params, no fractals.
PackManifest tiny_manifest(const std::string& graph_text = kTinyGraph) {
    PackManifest m;
    m.name = "tiny";
    m.compiler = "fgc test";
    m.graph_hash = content_hash(graph_text);
    ManifestSpecConstant eps;
    eps.id = 1;
    eps.name = "epsilon";
    eps.type = ValueType::Float;
    eps.value = 0.5;
    m.spec_constants.push_back(eps);
    ManifestPass pass;
    pass.name = "main";
    pass.local_size = {8, 8, 1};
    pass.spec_constants = {1};
    m.passes.push_back(pass);
    return m;
}

// Builds a pack from a manifest JSON, a graph text and SPIR-V chunks for the given pass names.
Bytes make_pack(const nlohmann::json& manifest, const std::string& graph_text, const std::vector<std::string>& passes) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", graph_text));
    for (const auto& p : passes) w.add(std::make_unique<SpirvChunk>(p, tiny_spirv()));
    return w.bytes();
}

// Rebuilds a pack from what the reader returned: same chunks, same order.
Bytes rewrite(const Pack& pack) {
    PackWriter w;
    for (const auto& c : pack.chunks) {
        if (c.tag == kTagManifest) w.add(std::make_unique<ManifestChunk>(pack.manifest_json));
        else if (c.tag == kTagGraph) w.add(std::make_unique<TextChunk>(kTagGraph, "", pack.graph));
        else if (c.tag == kTagSourceMap) w.add(std::make_unique<TextChunk>(kTagSourceMap, "", pack.source_map.dump()));
        else if (c.tag == kTagSpirv) w.add(std::make_unique<SpirvChunk>(c.name, pack.spirv.at(c.name)));
        else if (c.tag == kTagGlsl) w.add(std::make_unique<TextChunk>(kTagGlsl, c.name, pack.glsl.at(c.name)));
        else if (c.tag == kTagEnvironment) w.add(std::make_unique<EnvironmentChunk>(*pack.environment));
        else ADD_FAILURE() << "unexpected chunk " << tag_text(c.tag);
    }
    return w.bytes();
}

// The SpecId decorations a SPIR-V module declares (OpDecorate = 71, SpecId = 1).
std::set<std::uint32_t> declared_spec_ids(const std::vector<std::uint32_t>& words) {
    std::set<std::uint32_t> ids;
    for (std::size_t i = 5; i < words.size();) {
        std::uint32_t count = words[i] >> 16, opcode = words[i] & 0xffffu;
        if (count == 0) break;
        if (opcode == 71 && count >= 4 && i + 3 < words.size() && words[i + 2] == 1) ids.insert(words[i + 3]);
        i += count;
    }
    return ids;
}

// --- What the compiler writes reads back -----------------------------------------------------

TEST(Pack, a_compiled_pack_reads_back_with_the_same_manifest_spirv_graph_and_source_map) {
    const auto& result = gallery();
    ASSERT_FALSE(result.passes.empty());
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);

    EXPECT_EQ(pack->version_major, kPackVersionMajor);
    EXPECT_EQ(pack->version_minor, kPackVersionMinor);
    EXPECT_EQ(pack->file_size, gallery_pack().size());
    EXPECT_EQ(manifest_to_json(pack->manifest), manifest_to_json(result.manifest));
    EXPECT_EQ(pack->manifest_json, manifest_to_json(result.manifest));

    ASSERT_EQ(pack->spirv.size(), result.passes.size());
    for (const auto& p : result.passes) {
        ASSERT_TRUE(pack->spirv.count(p.source.name)) << p.source.name;
        EXPECT_EQ(pack->spirv.at(p.source.name), p.spirv) << "SPIR-V of pass " << p.source.name;
    }
    EXPECT_EQ(pack->graph, result.graph_text);
    EXPECT_EQ(pack->manifest.graph_hash, content_hash(result.graph_text));

    nlohmann::json maps = nlohmann::json::object();
    for (const auto& p : result.passes) maps[p.source.name] = p.source.source_map.to_json();
    EXPECT_EQ(pack->source_map, maps);
    for (const auto& p : result.passes) {
        auto back = SourceMap::from_json(pack->source_map.at(p.source.name));
        EXPECT_EQ(back.size(), p.source.source_map.size()) << p.source.name;
    }
    EXPECT_TRUE(pack->glsl.empty()) << "GLSL is stored only when asked for";

    // Every chunk the reader lists lies inside the file, in order, without gaps.
    std::uint64_t at = pack_format::kHeaderSize;
    for (const auto& c : pack->chunks) {
        EXPECT_EQ(c.offset, at) << tag_text(c.tag) << " " << c.name;
        at += pack_format::kChunkHeaderSize + c.name.size() + c.payload_size + pack_format::kChecksumSize;
    }
    EXPECT_EQ(at, gallery_pack().size());
}

TEST(Pack, a_pack_with_debug_glsl_reads_back_with_the_glsl_of_every_pass) {
    const auto& result = gallery(true);
    auto pack = read_ok(pack_bytes(result));
    ASSERT_TRUE(pack);
    ASSERT_EQ(pack->glsl.size(), result.passes.size());
    for (const auto& p : result.passes) EXPECT_EQ(pack->glsl.at(p.source.name), p.source.glsl) << p.source.name;
}

TEST(Pack, writing_reading_and_writing_again_gives_identical_bytes) {
    for (bool glsl : {false, true}) {
        SCOPED_TRACE(glsl ? "with GLSL chunks" : "without GLSL chunks");
        const Bytes original = glsl ? pack_bytes(gallery(true)) : gallery_pack();
        auto pack = read_ok(original);
        ASSERT_TRUE(pack);
        Bytes again = rewrite(*pack);
        ASSERT_EQ(again.size(), original.size());
        EXPECT_TRUE(again == original) << "the rewritten pack differs from what the compiler wrote";
        auto pack2 = read_ok(again);
        ASSERT_TRUE(pack2);
        EXPECT_EQ(rewrite(*pack2), again);
    }
}

TEST(Pack, compiling_the_same_graph_twice_gives_identical_packs) {
    std::string text = read_text(std::string(FG_SOURCE_DIR) + "/graphs/gallery/mandelbulb.json");
    Diagnostics diag;
    auto again = compile_graph(text, NodeLibrary::builtin(), CompileOptions{}, diag);
    ASSERT_TRUE(again) << diag.format();
    EXPECT_TRUE(pack_bytes(*again) == gallery_pack());
}

// --- Damage is detected -------------------------------------------------------------------

TEST(Pack, flipping_any_single_byte_of_a_pack_is_detected) {
    Bytes bytes = gallery_pack();
    ASSERT_GT(bytes.size(), 20000u) << "the gallery pack should be a real one";
    auto start = std::chrono::steady_clock::now();
    std::size_t accepted = 0, silent = 0;
    auto flip_all = [&](std::uint8_t mask, std::size_t stride) {
        for (std::size_t i = 0; i < bytes.size(); i += stride) {
            bytes[i] ^= mask;
            Diagnostics diag;
            auto pack = read_pack(bytes, diag);
            bytes[i] ^= mask;
            if (pack) {
                if (++accepted <= 5) ADD_FAILURE() << "flipping bit mask 0x" << std::hex << int(mask) << std::dec
                                                   << " at byte " << i << " went unnoticed";
            } else if (!diag.has_errors() || !diag.items().front().byte) {
                if (++silent <= 5) ADD_FAILURE() << "byte " << i << ": refused without an error naming a byte offset";
            }
        }
    };
    flip_all(0x01, 1);   // every byte
    flip_all(0x80, 7);   // the top bit, on a sample
    flip_all(0xff, 13);  // a whole byte, on another sample
    auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(accepted, 0u);
    EXPECT_EQ(silent, 0u);
    EXPECT_TRUE(bytes == gallery_pack());
    RecordProperty("flip_ms", static_cast<int>(ms));
    std::printf("[ info     ] %zu bytes, %.0f ms for all flips\n", bytes.size(), ms);
}

TEST(Pack, every_truncation_of_a_pack_is_refused) {
    const Bytes& full = gallery_pack();
    for (std::size_t n = 0; n < full.size(); ++n) {
        Diagnostics diag;
        auto pack = read_pack(std::span<const std::uint8_t>(full.data(), n), diag);
        ASSERT_FALSE(pack) << "a " << n << "-byte prefix was accepted";
        ASSERT_TRUE(diag.has_errors()) << n;
        ASSERT_TRUE(diag.items().front().byte) << n;
    }
}

TEST(Pack, every_truncation_is_refused_even_when_the_header_size_is_patched_to_match) {
    // The header's size field alone would catch a plain truncation; here it agrees with the cut, so
    // the chunk walk must notice that the last chunk runs past the end.
    const Bytes& full = gallery_pack();
    Bytes cut;
    for (std::size_t n = pack_format::kHeaderSize; n < full.size(); ++n) {
        cut.assign(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(n));
        put_le(cut, 16, n, 8);
        reseal_header(cut);
        Diagnostics diag;
        auto pack = read_pack(cut, diag);
        ASSERT_FALSE(pack) << "a " << n << "-byte prefix with a matching header was accepted";
        ASSERT_TRUE(diag.has_errors()) << n;
        const auto& d = diag.items().front();
        ASSERT_TRUE(d.byte) << n;
        ASSERT_LE(*d.byte, n) << d.message;
        ASSERT_NE(d.message.find("truncated"), std::string::npos) << n << ": " << d.message;
    }
}

TEST(Pack, a_wrong_magic_is_refused_at_byte_0) {
    Bytes bytes = gallery_pack();
    bytes[0] = 'X';
    auto r = read_expecting_refusal(bytes);
    EXPECT_TRUE(has_error(r, "does not start with \"FGPK\"", 0));
    EXPECT_TRUE(has_error(read_expecting_refusal(Bytes{}), "not a Fractograph pack", 0));
    EXPECT_TRUE(has_error(read_expecting_refusal(Bytes{'F', 'G'}), "not a Fractograph pack", 0));
    EXPECT_TRUE(has_error(read_expecting_refusal(Bytes{'{', '"', 'f', 'o'}), "not a Fractograph pack", 0));
}

TEST(Pack, a_newer_major_version_is_refused_naming_both_versions) {
    Bytes bytes = gallery_pack();
    set_version(bytes, kPackVersionMajor + 1, 3);
    auto r = read_expecting_refusal(bytes);
    std::string expected_pack = std::to_string(kPackVersionMajor + 1) + ".3";
    std::string expected_build = "(" + std::to_string(kPackVersionMajor) + ".x)";
    EXPECT_TRUE(has_error(r, "pack format " + expected_pack + " is newer than this build reads " + expected_build, 4))
        << r.text();

    // The same pack with the current version reads: it is the version check that refused.
    set_version(bytes, kPackVersionMajor, kPackVersionMinor);
    EXPECT_TRUE(read_ok(bytes));

    set_version(bytes, 0, 0);
    EXPECT_TRUE(has_error(read_expecting_refusal(bytes), "version 0", 4));
}

TEST(Pack, a_header_field_changed_without_its_checksum_is_refused_at_the_checksum) {
    Bytes bytes = gallery_pack();
    put_le(bytes, 4, kPackVersionMajor + 1, 2);  // no reseal
    EXPECT_TRUE(has_error(read_expecting_refusal(bytes), "header checksum mismatch", 24));
}

TEST(Pack, extra_bytes_after_the_last_chunk_are_refused) {
    Bytes bytes = gallery_pack();
    std::size_t end = bytes.size();
    bytes.insert(bytes.end(), 8, 0);
    // The header's file size no longer matches...
    EXPECT_TRUE(has_error(read_expecting_refusal(bytes), "extra bytes at the end", 16));
    // ...and when it is patched to match, the chunk walk finds the trailing bytes.
    put_le(bytes, 16, bytes.size(), 8);
    reseal_header(bytes);
    EXPECT_TRUE(has_error(read_expecting_refusal(bytes), "8 bytes follow the last chunk", end));
}

TEST(Pack, a_chunk_with_a_wrong_checksum_is_refused_with_its_offset_and_tag_in_the_message) {
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);
    const PackChunkInfo* target = nullptr;
    std::size_t index = 0;
    for (std::size_t i = 0; i < pack->chunks.size(); ++i)
        if (pack->chunks[i].tag == kTagSpirv) {
            target = &pack->chunks[i];
            index = i;
            break;
        }
    ASSERT_TRUE(target);
    std::uint64_t checksum_at =
        target->offset + pack_format::kChunkHeaderSize + target->name.size() + target->payload_size;

    // Damage the stored checksum itself, then (separately) one payload byte.
    for (std::uint64_t at : {checksum_at, checksum_at - 1}) {
        Bytes bytes = gallery_pack();
        bytes[at] ^= 0x10;
        auto r = read_expecting_refusal(bytes);
        std::string what = "chunk " + std::to_string(index + 1) + " ('SPRV') " + target->name + ": checksum mismatch";
        EXPECT_TRUE(has_error(r, what, checksum_at)) << r.text();
        // The formatted line names the byte offset too.
        EXPECT_NE(r.text().find("byte " + std::to_string(checksum_at) + ": "), std::string::npos) << r.text();
    }
}

// --- The manifest and the chunks agree ---------------------------------------------------------

TEST(Pack, a_hand_made_pack_with_a_consistent_manifest_reads) {
    auto pack = read_ok(make_pack(manifest_to_json(tiny_manifest()), kTinyGraph, {"main"}));
    ASSERT_TRUE(pack);
    EXPECT_EQ(pack->manifest.passes.size(), 1u);
    EXPECT_EQ(pack->spirv.at("main"), tiny_spirv());
}

TEST(Pack, a_manifest_listing_a_pass_without_spirv_is_refused) {
    // The compiled pack without its last SPIR-V chunk.
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);
    std::string dropped = pack->chunks.back().name;
    ASSERT_EQ(pack->chunks.back().tag, kTagSpirv);
    pack->chunks.pop_back();
    pack->spirv.erase(dropped);
    auto r = read_expecting_refusal(rewrite(*pack));
    EXPECT_TRUE(has_error(r, "manifest lists pass '" + dropped + "' but the pack has no SPIR-V for it",
                          pack_format::kHeaderSize))
        << r.text();

    // A hand-made one.
    auto m = tiny_manifest();
    ManifestPass second;
    second.name = "second";
    m.passes.push_back(second);
    r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "manifest lists pass 'second' but the pack has no SPIR-V for it", pack_format::kHeaderSize));
}

TEST(Pack, a_spirv_chunk_that_belongs_to_no_pass_is_refused) {
    auto r = read_expecting_refusal(make_pack(manifest_to_json(tiny_manifest()), kTinyGraph, {"main", "stray"}));
    EXPECT_TRUE(has_error(r, "SPIR-V chunk 'stray' belongs to no pass in the manifest", pack_format::kHeaderSize))
        << r.text();
}

TEST(Pack, a_spirv_chunk_that_is_not_spirv_is_refused) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<TextChunk>(kTagSpirv, "main", "void main() {}"));
    Bytes bytes = w.bytes();
    auto pack = read_ok(make_pack(manifest_to_json(tiny_manifest()), kTinyGraph, {"main"}));
    ASSERT_TRUE(pack);
    auto r = read_expecting_refusal(bytes);
    EXPECT_TRUE(has_error(r, "SPIR-V chunk 'main' does not hold a SPIR-V module", pack->chunks.back().offset))
        << r.text();
}

TEST(Pack, a_manifest_whose_graph_hash_does_not_match_the_grph_chunk_is_refused) {
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);
    pack->graph += " ";  // the graph changed after compiling
    auto r = read_expecting_refusal(rewrite(*pack));
    EXPECT_TRUE(has_error(r, "the manifest's graph hash does not match the source graph chunk", pack_format::kHeaderSize))
        << r.text();

    auto m = tiny_manifest();
    m.graph_hash = "0123456789abcdef";
    r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "graph hash does not match"));
}

TEST(Pack, an_environment_image_reads_back_and_a_scene_that_names_one_needs_it) {
    auto m = tiny_manifest();
    m.scene.environment = SceneSettings::Environment{};
    m.scene.environment->image = "sky.exr";
    auto r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "the scene's environment is the image 'sky.exr', but the pack has no environment chunk (ENVI)",
                          pack_format::kHeaderSize))
        << r.text();

    EnvironmentImage sky{2, 1, {1, 2, 3, 4, 5, 6, 7, 0xffff}};
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(m)));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    w.add(std::make_unique<EnvironmentChunk>(sky));
    auto pack = read_ok(w.bytes());
    ASSERT_TRUE(pack);
    ASSERT_TRUE(pack->environment);
    EXPECT_EQ(*pack->environment, sky);

    EnvironmentImage short_of_texels{3, 1, {1, 2, 3, 4}};
    PackWriter bad;
    bad.add(std::make_unique<ManifestChunk>(manifest_to_json(m)));
    bad.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    bad.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    bad.add(std::make_unique<EnvironmentChunk>(short_of_texels));
    EXPECT_TRUE(has_error(read_expecting_refusal(bad.bytes()), "the environment chunk holds 16 bytes; a 3x1 image needs 32"));
}

TEST(Pack, a_pack_without_a_manifest_is_refused) {
    PackWriter w;
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    auto r = read_expecting_refusal(w.bytes());
    EXPECT_TRUE(has_error(r, "the pack has no manifest chunk (MANI)", pack_format::kHeaderSize)) << r.text();

    PackWriter empty;
    EXPECT_TRUE(has_error(read_expecting_refusal(empty.bytes()), "no manifest chunk", pack_format::kHeaderSize));
}

TEST(Pack, a_pack_without_a_source_graph_is_refused) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    EXPECT_TRUE(has_error(read_expecting_refusal(w.bytes()), "no source graph chunk (GRPH)", pack_format::kHeaderSize));
}

TEST(Pack, a_chunk_that_appears_twice_is_refused) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    EXPECT_TRUE(has_error(read_expecting_refusal(w.bytes()), "chunk 'SPRV' main appears twice"));
}

TEST(Pack, a_manifest_that_is_not_valid_json_is_refused) {
    PackWriter w;
    w.add(std::make_unique<TextChunk>(kTagManifest, "", "{\"version\": 1,"));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    EXPECT_TRUE(has_error(read_expecting_refusal(w.bytes()), "the manifest chunk is not valid JSON",
                          pack_format::kHeaderSize));
}

TEST(Pack, a_manifest_with_a_duplicate_specialization_constant_id_is_refused) {
    auto m = tiny_manifest();
    ManifestSpecConstant again = m.spec_constants.front();
    again.name = "max_steps";
    again.type = ValueType::Int;
    again.value = 256;
    m.spec_constants.push_back(again);  // id 1 a second time
    auto r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "specialization constant id 1 listed twice", pack_format::kHeaderSize)) << r.text();

    // Also in the compiled pack's manifest.
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);
    auto j = pack->manifest_json;
    ASSERT_GE(j["spec_constants"].size(), 2u);
    auto id = j["spec_constants"][0]["id"].get<std::uint32_t>();
    j["spec_constants"][1]["id"] = id;
    r = read_expecting_refusal(make_pack(j, pack->graph, {}));
    EXPECT_TRUE(has_error(r, "specialization constant id " + std::to_string(id) + " listed twice"));
}

TEST(Pack, specialization_constant_id_0_is_refused) {
    auto m = tiny_manifest();
    ManifestSpecConstant zero;
    zero.id = 0;
    zero.name = "zero";
    m.spec_constants.push_back(zero);
    auto r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "specialization constant id 0 is reserved", pack_format::kHeaderSize)) << r.text();
    bool pointer = false;
    for (const auto& d : r.diag.items()) pointer |= d.pointer == "/manifest/spec_constants/1/id";
    EXPECT_TRUE(pointer) << r.text();
}

TEST(Pack, a_pass_referring_to_an_unlisted_specialization_constant_is_refused) {
    auto m = tiny_manifest();
    m.passes.front().spec_constants.push_back(7);
    auto r = read_expecting_refusal(make_pack(manifest_to_json(m), kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "refers to a specialization constant the manifest does not list")) << r.text();
}

TEST(Pack, a_pass_listing_an_unknown_dispatch_constant_is_refused_and_one_without_any_reads) {
    auto m = tiny_manifest();
    auto j = manifest_to_json(m);
    j["passes"][0].erase("dispatch_constants");   // as an older fgc wrote it
    EXPECT_TRUE(read_ok(make_pack(j, kTinyGraph, {"main"})));
    j["passes"][0]["dispatch_constants"] = {kSpecProjection.id, 59};
    auto r = read_expecting_refusal(make_pack(j, kTinyGraph, {"main"}));
    EXPECT_TRUE(has_error(r, "is not a dispatch constant of this runtime")) << r.text();
    bool pointer = false;
    for (const auto& d : r.diag.items()) pointer |= d.pointer == "/manifest/passes/0/dispatch_constants/1";
    EXPECT_TRUE(pointer) << r.text();
}

TEST(Pack, an_unknown_chunk_tag_in_a_pack_of_this_version_is_refused_but_skipped_in_a_newer_minor_version) {
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<TextChunk>(ChunkTag{'X', 'T', 'R', 'A'}, "future", "a chunk kind added later"));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    Bytes bytes = w.bytes();
    ASSERT_EQ(get_le(bytes, 4, 2), 1u);
    ASSERT_EQ(get_le(bytes, 6, 2), kPackVersionMinor);

    auto r = read_expecting_refusal(bytes);
    // The XTRA chunk follows MANI and GRPH (neither has a name).
    std::uint64_t per_chunk = pack_format::kChunkHeaderSize + pack_format::kChecksumSize;
    std::uint64_t xtra_at = pack_format::kHeaderSize + per_chunk + manifest_to_json(tiny_manifest()).dump(2).size() +
                            per_chunk + kTinyGraph.size();
    EXPECT_TRUE(has_error(r, fmt::format("unknown chunk tag 'XTRA' in a 1.{} pack", kPackVersionMinor), xtra_at)) << r.text();

    set_version(bytes, kPackVersionMajor, 0);   // an older pack: its unknown tags are damage too
    EXPECT_TRUE(has_error(read_expecting_refusal(bytes), "unknown chunk tag 'XTRA' in a 1.0 pack", xtra_at));

    set_version(bytes, kPackVersionMajor, kPackVersionMinor + 1);
    auto pack = read_ok(bytes);
    ASSERT_TRUE(pack);
    EXPECT_EQ(pack->version_minor, kPackVersionMinor + 1);
    EXPECT_EQ(pack->spirv.at("main"), tiny_spirv());
    EXPECT_EQ(pack->chunks.size(), 4u) << "the skipped chunk is still listed";

    // A tag that is not four capital letters is damage, whatever the version.
    PackWriter bad;
    bad.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    bad.add(std::make_unique<TextChunk>(ChunkTag{'x', 't', '\0', '!'}, "", "?"));
    Bytes bad_bytes = bad.bytes();
    set_version(bad_bytes, kPackVersionMajor, kPackVersionMinor + 1);
    EXPECT_TRUE(has_error(read_expecting_refusal(bad_bytes), "('0x78740021'): the tag is not four capital letters"));
}

// Known reader bugs (see the report of the pack tests): enable once pack_reader.cpp refuses them.

TEST(Pack, a_second_manifest_chunk_under_another_name_is_refused) {
    // MANI, GRPH and SMAP are unique and unnamed: a second MANI under a name must not replace the first.
    auto second = manifest_to_json(tiny_manifest());
    second["name"] = "second";
    PackWriter w;
    w.add(std::make_unique<ManifestChunk>(manifest_to_json(tiny_manifest())));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    w.add(std::make_unique<TextChunk>(kTagManifest, "x", second.dump()));
    auto r = read_expecting_refusal(w.bytes());
    EXPECT_TRUE(r.refused) << "a pack with two manifests was read as '" << second["name"].get<std::string>() << "'";
    EXPECT_TRUE(r.first_error() && r.first_error()->byte) << r.text();
}

TEST(Pack, a_deeply_nested_manifest_is_refused_without_exhausting_the_stack) {
    // 10^6 nested arrays in "scene" (2 MB): copying such JSON recurses, so the reader refuses
    // documents nested deeper than 64 levels before anything copies them.
    auto m = manifest_to_json(tiny_manifest());
    m["scene"] = "DEEP";
    std::string text = m.dump(2);
    const std::size_t depth = 1000000;
    text.replace(text.find("\"DEEP\""), 6, std::string(depth, '[') + std::string(depth, ']'));
    PackWriter w;
    w.add(std::make_unique<TextChunk>(kTagManifest, "", text));
    w.add(std::make_unique<TextChunk>(kTagGraph, "", kTinyGraph));
    w.add(std::make_unique<SpirvChunk>("main", tiny_spirv()));
    auto r = read_expecting_refusal(w.bytes());
    EXPECT_TRUE(has_error(r, "", pack_format::kHeaderSize)) << r.text();
}

// --- What the compiler puts in the manifest ------------------------------------------------------

TEST(Pack, the_manifest_written_by_the_compiler_lists_every_specialization_constant_each_pass_declares) {
    auto pack = read_ok(gallery_pack());
    ASSERT_TRUE(pack);
    const auto& m = pack->manifest;
    ASSERT_FALSE(m.passes.empty());
    ASSERT_FALSE(m.spec_constants.empty());

    // Global knobs carry the ids of the table in common/spec_constants.h (1, 2, ...; below
    // kFirstNodeKnobId = 100); node knobs (<knob>.<node>) take ids from 100 on; id 0 is never used.
    std::set<std::uint32_t> ids;
    for (const auto& s : m.spec_constants) {
        EXPECT_NE(s.id, 0u) << s.name;
        EXPECT_TRUE(ids.insert(s.id).second) << "id " << s.id << " twice";
        const GlobalKnob* global = find_global_knob(s.name);
        if (s.id < kFirstNodeKnobId) {
            ASSERT_TRUE(global) << s.name << " has global id " << s.id << " but is not a global knob";
            EXPECT_EQ(s.id, global->id) << s.name;
            EXPECT_EQ(s.type, global->type) << s.name;
        } else {
            EXPECT_FALSE(global) << "global knob " << s.name << " has node knob id " << s.id;
            EXPECT_NE(s.name.find('.'), std::string::npos) << "a node knob is named <knob>.<node>: " << s.name;
        }
    }
    for (const auto& k : kGlobalKnobs) {
        EXPECT_GE(k.id, 1u) << k.name;
        EXPECT_LT(k.id, kFirstNodeKnobId) << k.name;
        EXPECT_TRUE(m.find_spec(k.id)) << "every pack carries global knob " << k.id << " " << k.name;
    }
    for (const auto& f : m.fractals) {
        if (f.bias_spec) EXPECT_GE(f.bias_spec, kFirstNodeKnobId) << f.node;
        if (f.iterations_spec) EXPECT_GE(f.iterations_spec, kFirstNodeKnobId) << f.node;
    }

    bool any = false;
    for (const auto& p : m.passes) {
        for (auto id : p.spec_constants) {
            EXPECT_TRUE(m.find_spec(id)) << "pass " << p.name << " uses id " << id << " which the manifest lacks";
            EXPECT_NE(id, 0u) << p.name;
        }
        for (auto id : p.dispatch_constants) EXPECT_TRUE(is_dispatch_constant(id)) << p.name << " id " << id;
        // What the manifest says each pass declares is what its SPIR-V declares: knobs and dispatch
        // constants.
        auto declared = declared_spec_ids(pack->spirv.at(p.name));
        std::set<std::uint32_t> listed(p.spec_constants.begin(), p.spec_constants.end());
        listed.insert(p.dispatch_constants.begin(), p.dispatch_constants.end());
        EXPECT_EQ(listed, declared) << "pass " << p.name;
        any |= !declared.empty();
    }
    EXPECT_TRUE(any) << "no pass declares a specialization constant";
}

}  // namespace
}  // namespace fg
