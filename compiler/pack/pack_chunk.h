#pragma once
// One chunk of a pack as it is written: each kind knows its tag, its name and how to serialise its
// payload (Filament's chunk-per-class idea); the writer only knows tags and sizes.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "chunk_tags.h"
#include "environment_image.h"

namespace fg {

class PackChunk {
public:
    virtual ~PackChunk() = default;
    virtual ChunkTag tag() const = 0;
    virtual std::string name() const { return {}; }
    virtual std::vector<std::uint8_t> payload() const = 0;
};

class ManifestChunk final : public PackChunk {
public:
    explicit ManifestChunk(nlohmann::json manifest) : manifest_(std::move(manifest)) {}
    ChunkTag tag() const override { return kTagManifest; }
    std::vector<std::uint8_t> payload() const override;

private:
    nlohmann::json manifest_;
};

class SpirvChunk final : public PackChunk {
public:
    SpirvChunk(std::string pass, std::vector<std::uint32_t> words) : pass_(std::move(pass)), words_(std::move(words)) {}
    ChunkTag tag() const override { return kTagSpirv; }
    std::string name() const override { return pass_; }
    std::vector<std::uint8_t> payload() const override;

private:
    std::string pass_;
    std::vector<std::uint32_t> words_;
};

// A text chunk: the source graph, the source map, a pass's GLSL.
class TextChunk final : public PackChunk {
public:
    TextChunk(ChunkTag tag, std::string name, std::string text)
        : tag_(tag), name_(std::move(name)), text_(std::move(text)) {}
    ChunkTag tag() const override { return tag_; }
    std::string name() const override { return name_; }
    std::vector<std::uint8_t> payload() const override;

private:
    ChunkTag tag_;
    std::string name_;
    std::string text_;
};

// The environment's image (environment_image.h).
class EnvironmentChunk final : public PackChunk {
public:
    explicit EnvironmentChunk(const EnvironmentImage& image) : image_(image) {}
    ChunkTag tag() const override { return kTagEnvironment; }
    std::vector<std::uint8_t> payload() const override { return environment_payload(image_); }

private:
    const EnvironmentImage& image_;
};

}  // namespace fg
