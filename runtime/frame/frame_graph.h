#pragma once
// The frame graph as data: the images and passes one stereo frame needs, for this pack and these
// settings, and nothing else. Each pass says which pack program it runs, which resource each of
// its shader bindings gets, what it reads and writes, and its push constants. `describe()` prints
// it (fgplay render --describe), so "only what the scene calls for" can be checked by reading.
#include <cstdint>
#include <string>
#include <vector>

#include "frame_settings.h"
#include "pack/manifest.h"

namespace fg {

enum class ImageFormat { R32F, RG32F, RGBA16F, RGBA8 };
const char* image_format_name(ImageFormat f);

struct FrameImage {
    std::string name;                  // "depth.left"
    std::uint32_t width = 0, height = 0;
    ImageFormat format = ImageFormat::R32F;
    std::string about;
};

// A storage buffer the graph owns, e.g. a tail queue; `reset` words are written at the start of
// every frame.
struct FrameBuffer {
    std::string name;
    std::uint64_t size = 0;
    std::vector<std::uint32_t> reset;
    std::string about;
};

struct FramePass {
    std::string label;                 // unique: "conemarch.left.L2"
    std::string program;               // the pack pass it runs: "conemarch"
    std::string timer;                 // GPU time is summed per timer group: "conemarch"
    std::vector<std::pair<std::string, std::string>> bindings;   // shader binding name -> resource
    std::vector<std::string> reads, writes;                       // images, for barriers and describe()
    std::vector<std::int32_t> push;                               // push-constant words
    std::uint32_t groups[3] = {1, 1, 1};
    std::int32_t counter_slot = -1;    // evaluation counter slot, -1 if the pass evaluates nothing
    std::string indirect;              // buffer whose first three words are the group counts
};

class FrameGraph {
public:
    static FrameGraph build(const PackManifest& manifest, const FrameSettings& settings, std::uint32_t centre_width,
                            std::uint32_t centre_height);

    const std::vector<FrameImage>& images() const { return images_; }
    const std::vector<FrameBuffer>& buffers() const { return buffers_; }
    const std::vector<FramePass>& passes() const { return passes_; }
    // Counter slots: one per pass program that marches ("conemarch", "reproject", "naive", "shade").
    const std::vector<std::string>& counter_groups() const { return counter_groups_; }
    const FrameImage* find_image(const std::string& name) const;
    std::string describe() const;

    // Used by the pass builders (conemarch_pass.cpp ...).
    void add_image(FrameImage image);
    void add_buffer(FrameBuffer buffer);
    void add_pass(FramePass pass);
    // A full-resolution pass of an eye, whose last push word is the pixel stride: with foveation
    // it runs as two dispatches, all pixels short of the periphery and every other pixel beyond.
    void add_pixel_pass(FramePass pass, int view);
    std::int32_t counter_slot(const std::string& group);

    std::uint32_t width = 0, height = 0, centre_width = 0, centre_height = 0;
    FrameSettings settings;
    EffectSet effects;
    bool has_post = false;             // the pack has a post pass: shade writes HDR for it
    std::uint32_t tail_after = 0;      // the tail_after knob: > 0 adds compacted tail passes
    bool manifest_has_tail = false;    // the pack has the tail program

private:
    std::vector<FrameImage> images_;
    std::vector<FrameBuffer> buffers_;
    std::vector<FramePass> passes_;
    std::vector<std::string> counter_groups_;
};

// Eyes and views as the shaders number them.
inline constexpr int kLeftView = 0, kRightView = 1, kCentreView = 2;
const char* view_name(int view);

// One builder per pass kind, each in its own file beside its shader template.
void add_naive_passes(FrameGraph& g, int view);
void add_conemarch_passes(FrameGraph& g, int view);
void add_reproject_pass(FrameGraph& g, int view);
void add_shade_pass(FrameGraph& g, int view);
void add_post_pass(FrameGraph& g, int view);
void add_fovea_pass(FrameGraph& g, int view);

}  // namespace fg
