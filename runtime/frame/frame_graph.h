#pragma once
// The frame graph as data: the images and passes one stereo frame needs, for this pack and these
// settings, and nothing else. Each pass binds resources by the shader's binding names and declares
// what it reads and writes; those declarations do the work (as Granite's render graph bakes its
// own): `batches()` orders the passes into groups separated by a barrier only where a hazard
// exists, the executor checks every binding against the shader's reflected access, and an image
// declared as history lives into the next frame. `describe()` prints it (fgplay render --describe).
//
// Adding a pass: its shader template (shaders/<name>.comp) and one builder file (<name>_pass.cpp)
// with `void add_<name>_passes(FrameGraph&)`, listed once in frame_passes.cpp.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "common/spec_constants.h"
#include "frame/dispatch_tiles.h"
#include "frame/shaders/gpu_interface.h"
#include "frame_settings.h"
#include "pack/manifest.h"

namespace fg {

enum class ImageFormat { R32F, RG32F, RGBA16F, RGBA32F, RGBA8, RGBA32UI };
const char* image_format_name(ImageFormat f);
std::uint32_t bytes_per_pixel(ImageFormat f);

struct FrameImage {
    std::string name;                  // "depth.left"
    std::uint32_t width = 0, height = 0;
    ImageFormat format = ImageFormat::R32F;
    std::string about;
    // Kept into the next frame: passes read the previous frame's contents as "<name>.previous"
    // (the executor keeps two images and swaps them after every frame).
    bool history = false;
};

// The name under which passes read a history image's previous frame, and back: the image a name
// stands for (itself, unless it is a previous frame's).
std::string previous(const std::string& image);
std::string current(const std::string& name);

// A storage buffer the graph owns, e.g. a work queue; `reset` words are written at the start of
// every frame.
struct FrameBuffer {
    std::string name;
    std::uint64_t size = 0;
    std::vector<std::uint32_t> reset;
    std::string about;
    // A tile list the executor writes whenever the frame's lens or fovea moves (dispatch_tiles.h).
    std::optional<std::pair<int, TileRegion>> tiles;
};

enum class Access { Read, Write, ReadWrite };

struct FramePass {
    std::string label;                 // unique: "conemarch.left.L2"
    std::string program;               // the pack pass it runs: "conemarch"
    std::string timer;                 // GPU time is summed per timer group: "march"
    std::vector<std::pair<std::string, std::string>> bindings;   // shader binding name -> resource
    std::vector<std::string> reads, writes;                       // resources, for barriers and describe()
    std::vector<std::byte> push;                                  // the push-constant struct's bytes
    // How it is dispatched: a grid of invocations (the executor divides by the shader's local
    // size), or group counts held by a buffer. With persistent lanes the shader takes its pixels
    // from a queue, and the executor dispatches a fixed share of the grid's groups instead.
    std::array<std::uint32_t, 3> invocations{1, 1, 1};
    bool persistent_lanes = false;
    std::string indirect;              // buffer whose first three words are the group counts (read)
    std::string tile_list;             // buffer of the tiles it dispatches, one workgroup each (dispatch_tiles.h)
    std::int32_t counter_slot = -1;    // evaluation counter slot, -1 if the pass evaluates nothing
    // Dispatch constants (common/spec_constants.h) this pass fixes, by id: passes of one program
    // with different values get their own pipelines. The executor adds the frame's projection.
    std::map<std::uint32_t, std::int32_t> specialize;

    // Binds `resource` to the shader's `binding` and declares the access.
    void bind(const std::string& binding, const std::string& resource, Access access);
    // A binding the shader declares that this pass never touches, its feature being off (the knob's
    // specialization constant compiles its code out): the graph declares nothing for it, and the
    // executor binds a shared stand-in of the binding's kind.
    void leave_unused(const std::string& binding) { unused.push_back(binding); }
    bool leaves_unused(const std::string& binding) const {
        return std::find(unused.begin(), unused.end(), binding) != unused.end();
    }
    std::vector<std::string> unused;
    template <class Push>
    void set_push(const Push& p) {
        static_assert(std::is_trivially_copyable_v<Push>);
        push.resize(sizeof p);
        std::memcpy(push.data(), &p, sizeof p);
    }
    bool reads_resource(const std::string& r) const;
    bool writes_resource(const std::string& r) const;
};

class FrameGraph {
public:
    // Throws std::runtime_error when the pack lacks a pass the graph needs (recompile it).
    static FrameGraph build(const PackManifest& manifest, const FrameSettings& settings, std::uint32_t centre_width,
                            std::uint32_t centre_height);

    const std::vector<FrameImage>& images() const { return images_; }
    const std::vector<FrameBuffer>& buffers() const { return buffers_; }
    const std::vector<FramePass>& passes() const { return passes_; }
    std::vector<FramePass>& passes() { return passes_; }
    // Counter slots: one per group of marching passes ("march.L0", "reproject", "shade"...).
    const std::vector<std::string>& counter_groups() const { return counter_groups_; }
    const FrameImage* find_image(const std::string& name) const;
    const FrameBuffer* find_buffer(const std::string& name) const;
    std::string describe() const;
    // What the images (two of each history image) and buffers take.
    std::uint64_t memory_bytes() const;

    // The passes in an order that keeps every declared dependency, grouped: the passes of a batch
    // depend on none of each other, and a barrier separates one batch from the next. A pass that
    // reads or writes what an earlier pass wrote, or writes what an earlier pass read, goes into a
    // later batch; independent passes (the two eyes' levels) share one.
    std::vector<std::vector<std::size_t>> batches() const;

    // Used by the pass builders (conemarch_pass.cpp ...). Adding an image of a name already taken
    // is fine if it is the same image (size and format), an error otherwise.
    void add_image(FrameImage image);
    void add_buffer(FrameBuffer buffer);
    void add_pass(FramePass pass);
    // Keeps an image into the next frame, where passes read it as previous(image).
    void keep_for_next_frame(const std::string& image);
    // A full-resolution pass of an eye, made by `make(stride)`: with foveation it runs as two
    // dispatches, all pixels short of the periphery (stride 1) and every other pixel beyond (stride 2).
    // A headset's eye dispatches tiles, so that it can leave out those its lens hides.
    template <class Make>
    void add_pixel_pass(int view, Make make) {
        FramePass full = make(1);
        full.invocations = {width, height, 1};
        if (!foveated(view)) {
            if (view != FG_VIEW_CENTRE && !is_panorama()) dispatch_tiles(full, view, TileRegion::Whole);
            add_pass(std::move(full));
            return;
        }
        FramePass periphery = make(2);
        periphery.label += ".periphery";
        periphery.invocations = {(width + 1) / 2, (height + 1) / 2, 1};
        dispatch_tiles(full, view, TileRegion::Fovea);
        dispatch_tiles(periphery, view, TileRegion::Periphery);
        add_pass(std::move(full));
        add_pass(std::move(periphery));
    }
    // An eye's pass dispatches only the tiles of `region` (its grid: the pass's invocations), where
    // the pack's shaders can and the pass takes its pixels from no queue.
    void dispatch_tiles(FramePass& pass, int view, TileRegion region);
    // Fixed foveation applies to the eyes, never to the centre view of stereo reprojection.
    bool foveated(int view) const { return settings.foveation > 0.0 && view != FG_VIEW_CENTRE; }
    std::int32_t counter_slot(const std::string& group);

    // The views whose images the frame outputs: both eyes, or the centre alone for a mono panorama.
    std::vector<int> output_views() const;
    bool is_panorama() const { return settings.projection != Projection::Perspective; }

    std::uint32_t width = 0, height = 0, centre_width = 0, centre_height = 0;
    // The size of each eye's final image: the marched size, or temporal upsampling's output size.
    std::uint32_t output_width = 0, output_height = 0;
    FrameSettings settings;
    EffectSet effects;
    std::uint32_t tail_after = 0;      // the tail_after knob: > 0 adds compacted tail passes
    bool persistent_lanes = false;     // the persistent_lanes knob (then there is no tail pass)
    // The reuse knob, where it can hold: per-eye perspective frames of a static float scene.
    bool reuse = false;
    // The shade_history knob, where it can hold: a static float scene in perspective whose shading
    // does not depend on the view direction (no rim, SSS, specular or reflection).
    bool shade_history = false;
    bool manifest_has_tail = false;    // the pack has the tail program
    // An eye's passes dispatch the tiles that hold their pixels (the fovea's, the periphery's, the
    // lens's): the tile_dispatch setting, where the pack's shaders can (an older pack's dispatch the
    // whole image).
    bool tile_dispatch = false;
    // The pack's conemarch can start a foveated periphery's pixels from level 2 (conemarch_pass.cpp).
    bool periphery_from_level_2 = false;
    // Temporal anti-aliasing (taa_pass.cpp), where it can hold: a static float scene in perspective.
    bool taa = false;
    // The image the shade and fovea passes write a view's picture to: its final image, or with
    // temporal anti-aliasing the jittered frame the taa pass resolves into it.
    std::string shaded_image(int view) const;

private:
    std::vector<FrameImage> images_;
    std::vector<FrameBuffer> buffers_;
    std::vector<FramePass> passes_;
    std::vector<std::string> counter_groups_;
};

// Eyes and views as the shaders number them (gpu_interface.h).
inline constexpr int kLeftView = FG_VIEW_LEFT, kRightView = FG_VIEW_RIGHT, kCentreView = FG_VIEW_CENTRE;
const char* view_name(int view);

// The images temporal anti-aliasing keeps into the next frame, at the output size (taa_pass.cpp):
// what a frame graph of another render size can take over (FrameExecutor::take_history).
std::vector<std::string> taa_history_images(const FrameGraph& graph);

}  // namespace fg
