//! pass: taa
//! needs: nothing
//! when: always
// Temporal anti-aliasing: each frame marches its rays through a jittered pixel grid (the eyes'
// frusta move by a sub-pixel offset, GpuFrame.jitter), and this pass blends the frame's samples
// into a per-eye history of the pictures before it, so a pixel converges towards the mean over its
// area instead of one point of it. Per pixel:
//
// - the sample's hit point (or, for a miss, its direction) projects exactly into the previous
//   frame's view: the scene is a static distance field, so that is where the pixel was;
// - the history there is fetched with a Lanczos-3 filter (a bilinear fetch re-filters it on every
//   frame of sub-pixel motion and blurs it away: 0.9-2.8 dB lost against Catmull-Rom, which in turn
//   loses 0.4-1.5 dB against Lanczos-3);
// - it is rejected where the previous frame saw something clearly in front of the point, against
//   its depth dilated by a 3x3 maximum: a fractal's depth varies inside a pixel, so a two-sided
//   test rejects a few percent of a still frame's pixels every frame and they never converge;
// - it is clipped towards the current 3x3 neighbourhood's mean, onto its YCoCg variance box (what
//   the history shows that the current samples cannot have is ghosting, or a change): 1.5 standard
//   deviations still, so a still head converges (1 clipped it to 38.8 dB of 16 samples, 1.5 to
//   42.8, the bulb at 96²), 1 at a pixel of motion per frame and beyond, where lag shows;
// - and blended with the current sample by a weight that grows with the motion (0.1 still, 0.2 at a
//   pixel per frame and beyond), so a moving picture carries less lag and resampling blur, and below
//   a pixel a frame with how far between texels the history falls (up to 0.35 halfway);
// - what is shown (not what is kept) sharpens slowly moving history by the blur its fetch adds
//   (TaaPush.sharpen, `--taa-sharpen`).
//
// When the head stops (GpuFrame.still_frames), each pixel averages its samples with equal weights:
// progressive refinement, the picture of 16 samples per pixel after 16 still frames.
//
// Temporal upsampling: the frame is marched at 1/1.5 or 1/2 of the output size per axis, and this
// pass writes the output size. Each output pixel takes the marched sample nearest to its centre,
// weighted by how far outside the pixel it falls, so a pixel fills from the samples that land in it
// as the jitter moves them over it (taa_phases: 36 or 64 offsets, 16 per output pixel). The history
// keeps each pixel's weight of samples (alpha): a new sample's share is its weight over the total,
// the total capped at 1 / blend - 1 under motion (so a pixel that just lost its history fills in
// at once), uncapped when still (a plain mean). Where history is lost, the pixel starts from the
// marched frame filtered up to the output size.
//
// The history holds the tone-mapped colour in linear light, so it converges to the mean of the
// samples as --samples averages them; working after the tone map keeps one bright highlight from
// dominating a neighbourhood.

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 3, rgba8) uniform readonly image2D fg_jittered;     // this frame, display-encoded, marched size
layout(set = 0, binding = 4, r32f) uniform readonly image2D fg_depth;         // this frame's hit distances
layout(set = 0, binding = 5, rgba32f) uniform readonly image2D fg_history;    // the previous result, linear; alpha: weight
layout(set = 0, binding = 6, r32f) uniform readonly image2D fg_history_depth;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D fg_resolved;  // this frame's result, output size
layout(set = 0, binding = 8, r32f) uniform writeonly image2D fg_resolved_depth;
layout(set = 0, binding = 9, rgba8) uniform writeonly image2D fg_final;       // the result, display-encoded
layout(push_constant) uniform FgTaaPush { TaaPush pc; };

const float kStillBlend = 0.1;     // the weight of a new sample with a still head
const float kMovingBlend = 0.2;    // ... at one pixel of motion per frame and beyond
const float kHalfwayBlend = 0.25;  // ... more, slowly moving, where the history falls between texels
const float kInFront = 0.95;       // history is rejected where the previous depth is nearer than this
const float kStillSigmas = 1.5;    // the clip box: mean +- this many standard deviations, still
const float kMovingSigmas = 1.0;   // ... at one pixel of motion per frame and beyond
const float kOutsideFalloff = 0.25;  // output pixels: a sample this far outside a pixel weighs e^-0.5

vec3 fg_ycocg(vec3 c)
{
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 fg_rgb(vec3 y)
{
    return vec3(y.x + y.y - y.z, y.x + y.z, y.x - y.y - y.z);
}

// What of the picture a fade (a snap turn's, the head in the surface) leaves: the shade pass scales
// the displayed values by it. The history holds the unfaded picture, so a fade is no change of the
// scene and leaves no dark trail; this pass fades what it shows.
float fg_kept()
{
    return 1.0 - fg_scene.fade;
}

// Below this much of the picture left, 8-bit values hold too little of it to unfade.
const float kFadedOut = 0.05;

// A marched sample of this frame in linear light without the fade, clamped to the image.
vec3 fg_current(ivec2 pixel, ivec2 size)
{
    vec3 shown = imageLoad(fg_jittered, clamp(pixel, ivec2(0), size - 1)).rgb;
    return fg_srgb_to_linear(min(shown / max(fg_kept(), kFadedOut), vec3(1.0)));
}

// The history at a continuous position (pixel units, texel centres at i + 0.5): a Lanczos-3 filter
// over the 6x6 texels around it, clamped at the image's edges. Every frame of sub-pixel motion
// resamples the history, so the filter's loss compounds over the frames a pixel remembers: Lanczos-3
// passes detail up to half the Nyquist rate unchanged where Catmull-Rom (and bilinear far more)
// already loses 12 % of it at half a pixel (bench/taa_quality.py: +0.4 to +1.5 dB against
// Catmull-Rom on every trace, and less flicker).
float fg_lanczos3(float x)
{
    if (abs(x) < 1e-4) return 1.0;
    float px = 3.14159265 * x;
    return 3.0 * sin(px) * sin(px / 3.0) / (px * px);
}

vec3 fg_history_at(vec2 at, ivec2 size, float sharpen, out vec3 sharpened)
{
    vec2 s = at - 0.5;
    ivec2 base = ivec2(floor(s));
    vec2 f = s - vec2(base);
    // Tap i's weight is w[i + 1]; w[0] and w[7], outside the window, pad the sharpening below.
    float wx[8], wy[8];
    wx[0] = wy[0] = wx[7] = wy[7] = 0.0;
    for (int i = 1; i < 7; ++i) {
        wx[i] = fg_lanczos3(float(i - 3) - f.x);
        wy[i] = fg_lanczos3(float(i - 3) - f.y);
    }
    // The same taps sharpened: the filtered history less a share of its neighbours' one texel away
    // (an unsharp mask of the interpolated picture, in each axis).
    float sx[6], sy[6];
    for (int i = 0; i < 6; ++i) {
        sx[i] = (1.0 + sharpen) * wx[i + 1] - 0.5 * sharpen * (wx[i] + wx[i + 2]);
        sy[i] = (1.0 + sharpen) * wy[i + 1] - 0.5 * sharpen * (wy[i] + wy[i + 2]);
    }
    vec3 sum = vec3(0.0), sharp = vec3(0.0);
    float weight = 0.0, sharp_weight = 0.0;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i) {
            ivec2 texel = clamp(base + ivec2(i - 2, j - 2), ivec2(0), size - 1);
            vec3 h = imageLoad(fg_history, texel).rgb;
            float wij = wx[i + 1] * wy[j + 1];
            sum += wij * h;
            weight += wij;
            float sij = sx[i] * sy[j];
            sharp += sij * h;
            sharp_weight += sij;
        }
    sharpened = max(sharp / sharp_weight, vec3(0.0));
    return max(sum / weight, vec3(0.0));
}

// The farthest depth the previous frame saw around a texel (a miss is farther than anything).
float fg_farthest_before(ivec2 texel, ivec2 size)
{
    float farthest = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            float d = imageLoad(fg_history_depth, clamp(texel + ivec2(i, j), ivec2(0), size - 1)).x;
            farthest = max(farthest, d < 0.0 ? 1e30 : d);
        }
    return farthest;
}

// Where a point (or a miss's direction) was in the previous frame's output image, in its
// unjittered pixel coordinates (texel centres at i + 0.5), or a negative x when it was behind that
// view: its place in the previous marched frame of `size` pixels, `upscale` output pixels each.
vec2 fg_previous_position(GpuView o, vec3 towards, ivec2 size, float upscale)
{
    float z = dot(towards, o.forward.xyz);
    if (z <= 0.0) return vec2(-1.0);
    vec2 tangent = vec2(dot(towards, o.right.xyz), dot(towards, o.up.xyz)) / z;
    vec2 uv = vec2((tangent.x - o.tan_fov.x) / (o.tan_fov.y - o.tan_fov.x),
                   (o.tan_fov.w - tangent.y) / (o.tan_fov.w - o.tan_fov.z));
    return (uv * vec2(size) + fg_frame.jitter.zw) * upscale;
}

// Clips q towards the box's centre onto the box (Playdead's clip: keeps the history's hue where a
// clamp of each channel would not).
vec3 fg_clip(vec3 q, vec3 centre, vec3 extent)
{
    vec3 v = q - centre;
    vec3 a = abs(v / max(extent, vec3(1e-5)));
    float m = max(a.x, max(a.y, a.z));
    return m > 1.0 ? centre + v / m : q;
}

void main()
{
    ivec2 size = ivec2(fg_frame.eye_size);   // marched
    ivec2 out_size = imageSize(fg_final);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= out_size.x || pixel.y >= out_size.y) return;
    // Output pixels per marched pixel, exactly: the marched frustum reaches past the output's where
    // the output is no multiple of it (stereo_rig.h).
    float scale = pc.upscale;
    bool upsampling = scale > 1.0;
    vec2 centre = vec2(pixel) + 0.5;
    // The marched sample nearest the pixel's centre (marched pixel k's sample lies at k + 0.5 +
    // the jitter), its offset from the centre in output pixels, and its weight for this pixel: 1
    // inside it (always, without upsampling), falling off outside.
    ivec2 k = clamp(ivec2(floor(centre / scale - fg_frame.jitter.xy)), ivec2(0), size - 1);
    vec2 offset = (vec2(k) + 0.5 + fg_frame.jitter.xy) * scale - centre;
    vec2 outside = max(abs(offset) - 0.5, vec2(0.0));
    bool inside = outside == vec2(0.0);
    float weight = exp(-0.5 * dot(outside, outside) / (kOutsideFalloff * kOutsideFalloff));

    vec3 current = fg_current(k, size);
    float t = imageLoad(fg_depth, k).x;
    imageStore(fg_resolved_depth, pixel, vec4(t));
    // The neighbourhood's colour statistics, for the clip box, and upsampling, the marched frame
    // filtered to this pixel (a Gaussian of a pixel's width, separable), where history is lost.
    vec3 m1 = vec3(0.0), m2 = vec3(0.0), filtered = vec3(0.0), lowest = vec3(1e30), highest = vec3(-1e30);
    float filtered_weight = 0.0;
    vec3 gx = exp(-2.0 * pow(offset.x + vec3(-scale, 0.0, scale), vec3(2.0)));
    vec3 gy = exp(-2.0 * pow(offset.y + vec3(-scale, 0.0, scale), vec3(2.0)));
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            vec3 c = fg_current(k + ivec2(i, j), size);
            lowest = min(lowest, c);
            highest = max(highest, c);
            vec3 y = fg_ycocg(c);
            m1 += y;
            m2 += y * y;
            float g = gx[i + 1] * gy[j + 1];
            filtered += g * c;
            filtered_weight += g;
        }
    m1 /= 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - m1 * m1, vec3(0.0)));
    vec3 result = upsampling ? filtered / filtered_weight : current;
    float samples = 1.0;   // the weight of samples the result holds
    vec3 shown = result;   // what is displayed: the result, its history sharpened where it moves slowly

    if (fg_frame.taa_history != 0u && !fg_outside_lens(pc.view, centre / scale / vec2(size), vec2(0.0)) &&
        fg_kept() >= kFadedOut) {
        GpuView o = fg_frame.previous[pc.view];
        vec2 uv = (vec2(k) + 0.5) / vec2(size);
        vec3 rd = fg_ray_dir(pc.view, uv);
        vec3 p = fg_ray_origin(pc.view, uv) + rd * t;
        // A miss is a point at infinity: only its direction moves it.
        vec3 towards = t < 0.0 ? rd : p - o.origin.xyz;
        vec2 q = fg_previous_position(o, towards, size, scale);
        // Where this pixel was: the sample's previous position less its offset from the centre.
        vec2 at = q - offset;
        bool seen = q.x >= 0.0 && all(greaterThanEqual(at, vec2(0.0))) && all(lessThan(at, vec2(out_size)));
        if (seen) {
            float here = t < 0.0 ? 1e30 : length(towards);
            seen = fg_farthest_before(ivec2(floor(at)), out_size) >= kInFront * here;
        }
        if (fg_frame.still_frames > 0u) {
            // A still head: the history is this pixel's own, a plain mean of the samples that fell in
            // it since the head stopped (and the picture before, as one sample), so it converges to
            // their mean, the pixel's area sampled evenly.
            vec4 history = imageLoad(fg_history, pixel);
            // (Upsampled, that picture is the marched one filtered up, blurred: it weighs as little
            // as one marched pixel's share of the output's.)
            float before = fg_frame.still_frames == 1u ? min(history.a, 1.0 / (scale * scale)) : history.a;
            float w = inside ? 1.0 : 0.0;
            samples = before + w;
            result = (history.rgb * before + current * w) / samples;
            shown = result;
        } else if (seen) {
            float motion = length(at - centre);
            // Upsampled, the box comes from marched pixels `scale` output pixels apart: it is as much wider
            // (1 / scale tighter cost the bulb 2 dB under motion at 2, scale wider gained 0.8).
            float sigmas = mix(kStillSigmas, kMovingSigmas, clamp(motion, 0.0, 1.0)) * scale;
            float slow = 1.0 - clamp(motion, 0.0, 1.0);
            vec2 between = fract(at - 0.5);
            vec2 halfway = 4.0 * between * (1.0 - between);
            // What is shown sharpens the history by how much this frame's fetch blurred it (most
            // halfway between texels, and slowly moving, where the same loss repeats frame after
            // frame), within the range of the current neighbourhood and the history: it restores the
            // grooves the resampling washes out without lifting noise or aliasing above what the
            // samples show (slow orbits: detail 0.87-0.88 to 0.95-0.96 of the reference).
            float sharpen = pc.sharpen * slow * slow * max(halfway.x, halfway.y);
            vec3 sharp_history;
            vec3 history = fg_rgb(fg_clip(fg_ycocg(fg_history_at(at, out_size, sharpen, sharp_history)), m1, sigmas * sigma));
            vec3 shown_history = clamp(fg_rgb(fg_clip(fg_ycocg(sharp_history), m1, sigmas * sigma)),
                                       min(lowest, history), max(highest, history));
            // Below a pixel a frame the resampling's loss repeats frame after frame, most where the
            // history falls halfway between texels: there a new sample weighs more, so the picture
            // remembers fewer resamplings (slow orbits: detail 0.79 to 0.87, +1.1 dB; beyond a pixel
            // a frame the offsets vary and the extra weight only added noise).
            float blend = mix(kStillBlend, kMovingBlend, 1.0 - slow) + kHalfwayBlend * max(halfway.x, halfway.y) * slow;
            float before = min(imageLoad(fg_history, ivec2(floor(at))).a, 1.0 / blend - 1.0);
            samples = before + weight;
            result = (history * before + current * weight) / samples;
            shown = (shown_history * before + current * weight) / samples;
        }
    }
    vec3 rgb = max(result, vec3(0.0));
    imageStore(fg_resolved, pixel, vec4(rgb, samples));
    imageStore(fg_final, pixel, vec4(fg_linear_to_srgb(max(shown, vec3(0.0))) * fg_kept(), 1.0));
}
