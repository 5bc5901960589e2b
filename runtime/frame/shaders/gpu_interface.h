// The structs the GPU reads, declared once for C++ and GLSL (as zeux/niagara's shared headers): the
// frame and scene uniform blocks and every pass's push constants. The compiler pastes this file
// before common.glsl into every pass; the runtime includes it. Fields are grouped so that std140
// (uniform blocks) and C++ lay them out alike: vec4s, or a vec3 followed by one float, or four
// scalars; the static_asserts at the end check the offsets the shaders rely on.
#ifdef __cplusplus
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace fg {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uint = std::uint32_t;
#endif

// Views as the shaders number them: the eyes, and the centre eye that stereo reprojection marches.
const int FG_VIEW_LEFT = 0;
const int FG_VIEW_RIGHT = 1;
const int FG_VIEW_CENTRE = 2;

// How a pixel becomes a ray (GpuFrame.projection).
const uint FG_PROJECTION_PERSPECTIVE = 0u;
const uint FG_PROJECTION_EQUIRECT = 1u;
const uint FG_PROJECTION_ODS = 2u;

// Words per counter slot in the counters buffer (march_counters.glsl): evaluations, busy and all
// lane-iterations, rays cross-frame reuse could shorten, the thousandths it skipped, and the
// fractal iterations the evaluations ran.
const uint FG_COUNTER_WORDS = 6u;

// Persistent lanes (lane_queue.glsl): the most pixels one lane takes from the queue in a dispatch.
// llvmpipe ends every loop of a shader invocation once all its loops together ran 65535 iterations
// (LP_MAX_TGSI_LOOP_ITERATIONS), and it runs a dispatch's workgroups in order on a few threads, so
// unbounded lanes of its first workgroups would drain the queue and be cut off mid-ray, their
// pixels never written. The executor dispatches groups for twice the pixels at this bound.
const uint FG_LANE_PIXELS = 32u;

// ODS fades the eyes' separation to none towards the poles (from 60 degrees of latitude to 90, a
// smoothstep): near the zenith and nadir every column's eye looks at the same point from another
// place on the IPD circle, which swirls in a headset (Google's ODS guidance does the same).
const float FG_ODS_FADE_START = 1.04719755f;   // radians of latitude
const float FG_ODS_FADE_WIDTH = 0.52359878f;

// One view: an eye or the centre eye.
struct GpuView {
    vec4 origin;     // xyz eye position in scene units (relative to the anchor in double packs)
    vec4 right;      // xyz unit right axis
    vec4 up;         // xyz unit up axis
    vec4 forward;    // xyz unit forward axis
    vec4 tan_fov;    // tangents of the frustum edges: x left (< 0), y right, z down (< 0), w up
    vec2 lens_centre;   // the lens mask: an ellipse in uv; radii 0 when off
    vec2 lens_radii;
};

// Set every frame (set 0, binding 0).
struct GpuFrame {
    GpuView views[3];
    uvec2 eye_size;          // every eye image, in pixels
    uvec2 centre_size;       // the centre eye's image (wider: it covers both eyes)
    uint frame_index;
    uint cone_levels;
    uint projection;         // FG_PROJECTION_*
    uint unused_0;
    float seconds;           // scene time
    float world_scale;       // scene units per metre of the viewer
    float ipd;               // interpupillary distance in scene units
    // The half-diagonal angle of one output pixel (radians): the hit threshold and the normal taps
    // follow it at every march resolution, so supersampling, foveation and a reduced resolution
    // change a picture's noise, never which fractal it shows.
    float detail_cone;
    float pixel_cone_tan;    // half-diagonal angle of one marched full-resolution pixel (radians)
    float pixel_tan;         // tangent per pixel
    float fovea_radius;      // in half image heights; 0: foveation off
    float fovea_blend;       // width of the band where fovea and periphery blend
    // The camera (centre eye) in double, as hi + lo floats. Packs of precision "double" evaluate
    // the scene at the anchor + p, and every view origin is then relative to it.
    vec4 anchor_hi;
    vec4 anchor_lo;
    // Cross-frame reuse: the eyes of the frame before, whose conemarch levels the passes read as
    // history, and whether they hold for this frame (1: the same static scene, 0: the first frame,
    // a changed parameter or a new pack).
    GpuView previous[2];
    uint reuse;
    uint shade_history;      // 1: the previous frame's shading holds for this one (FG_SHADE_HISTORY)
    uint taa_history;        // 1: temporal anti-aliasing's history holds (the same static scene)
    // Frames before this one that saw exactly this view (jitter aside), since it last moved: a still
    // head's history is then a plain mean of its samples, which converges (0: moving).
    uint still_frames;
    // Sub-pixel jitter of the eyes' pixel grids (StereoSettings::jitter), in pixels, x right, y
    // down: xy this frame's, zw the previous frame's (whose views are `previous`).
    vec4 jitter;
    // Area lights while offline samples accumulate: x this sample's index, whose point of a light's
    // disc each pixel draws from its own scrambling of one sequence (fg_light_sample), z 1; all 0
    // in a single frame, which takes light.soft_shadow's cone-angle penumbra instead.
    vec4 area_light;
};

// The scene's settings (set 0, binding 1): uniforms, so editing them never recompiles.
struct GpuScene {
    vec4 light_dir;          // xyz unit direction towards the light
    vec4 light_color;
    vec4 ambient;
    vec4 sss_color;
    vec4 rim_color;
    vec4 albedo;             // used when the graph binds no albedo
    vec4 bg_top;
    vec4 bg_bottom;
    vec3 fog_color;
    float fog_density;       // extinction per scene unit
    vec3 glow_color;         // colour times intensity
    float glow_falloff;      // distance at which glow drops to 1/e
    vec3 bounds_centre;      // rays outside this sphere miss
    float bounds_radius;
    vec3 bounds_centre_lo;   // what float loses of the centre (double packs add it)
    uint auxiliary_lights;   // how many of auxiliary_light hold a light (FG_HAS_LIGHTS)
    float exposure;
    float far_limit;         // the march's far limit, in scene units
    float vignette;          // the comfort vignette's strength (0: none)
    float fade;              // 0 none, 1 black: snap turns, the head in the surface
    // Each auxiliary light: xyz a position (w 1: a point light, whose colour is its intensity one
    // scene unit away) or the unit direction towards it (w 0); its colour.
    vec4 auxiliary_light[4];
    vec4 auxiliary_color[4];
    // The environment (FG_HAS_ENVIRONMENT): rgb its colour times intensity, w its turn about +y
    // (radians, counter-clockwise from above).
    vec4 environment;
    // Fog (FG_HAS_FOG): x the density's falloff per scene unit up (0: homogeneous), y the height
    // where the density is fog_density; z the share of the main light it scatters (0: no light
    // shafts), w the scattering's anisotropy (Henyey-Greenstein g).
    vec4 fog_height;
};

// Push constants, one struct per pass. `stride` is 1 for a full-resolution dispatch, 2 for the
// foveated periphery's (every other pixel).
struct ConemarchPush {
    int view;
    int level;               // 0 = full resolution
    int top;                 // 1 for the coarsest level: no parent
    int counter_slot;
    int stride;
};

struct NaivePush {
    int view;
    int counter_slot;
    int stride;
};

struct TailPush {
    int view;
    int counter_slot;
};

struct ReprojectPush {
    int view;                // left or right
    int counter_slot;
    int levels;              // levels of the centre atlas, 0 .. levels - 1
    int stride;
};

struct ShadePush {
    int view;
    int reuse;               // 1: take the other eye's shading where it sees the same point
    int stride;
    int hdr;                 // 1: also store the tone map's input (FrameSettings::hdr)
};

struct ResolvePush {
    int view;
    int levels;              // 1: also the level-0 atlas (conemarch), 0: depth and glow only (naive)
};

struct AovPush {
    int view;
};

struct FoveaPush {
    int view;
};

struct TaaPush {
    int view;
    float upscale;   // output pixels per marched pixel (temporal upsampling), 1 without
    float sharpen;   // the shown picture's sharpening of slowly moving history (0: none)
};

struct ProbePush {
    int count;
    float normal_step;
};

#ifdef __cplusplus
static_assert(sizeof(GpuView) == 96);
static_assert(offsetof(GpuFrame, eye_size) == 288 && offsetof(GpuFrame, frame_index) == 304);
static_assert(offsetof(GpuFrame, seconds) == 320 && offsetof(GpuFrame, pixel_cone_tan) == 336);
static_assert(offsetof(GpuFrame, anchor_hi) == 352 && offsetof(GpuFrame, previous) == 384);
static_assert(offsetof(GpuFrame, reuse) == 576 && offsetof(GpuFrame, jitter) == 592 && sizeof(GpuFrame) == 624);
static_assert(offsetof(GpuScene, fog_color) == 128 && offsetof(GpuScene, glow_color) == 144);
static_assert(offsetof(GpuScene, bounds_centre) == 160 && offsetof(GpuScene, bounds_centre_lo) == 176);
static_assert(offsetof(GpuScene, exposure) == 192 && offsetof(GpuScene, auxiliary_light) == 208 && sizeof(GpuScene) == 368);
}  // namespace fg
#endif
