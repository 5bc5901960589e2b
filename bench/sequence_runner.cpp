#include "sequence_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>

#include "bench_views.h"
#include "common/embedded_file.h"
#include "compiler.h"
#include "frame/accuracy_metrics.h"
#include "frame/gpu_uniforms.h"
#include "frame/headless_renderer.h"
#include "frame/lens_mask.h"
#include "frame/strict_reference.h"
#include "frame_measures.h"
#include "gpu_clock.h"
#include "head_trace.h"
#include "offline/jittered_samples.h"
#include "pack/pack_reader.h"
#include "sequence_report.h"
#include "sequence_settings.h"
#include "vk/context.h"

namespace fg {
std::span<const EmbeddedFile> embedded_sequence_scenes();   // generated (bench/fg_bench.cmake)
}

namespace fg::bench {

namespace {

// Counting evaluations takes a frame of its own; one frame in six samples a 90-frame trace 15 times.
constexpr int kCountEvery = 6, kQuickCountEvery = 4;

// A scene to fly: a graph file or a pack file, or a gallery graph carried inside the binary.
struct SceneSource {
    std::string name, path;   // path empty: `graph_text` is the graph
    std::string graph_text;
};

std::vector<SceneSource> default_scenes(bool quick) {
    std::vector<SceneSource> out;
    for (std::string name : {"mandelbulb", "mandelbox", "kleinian"})
        for (const auto& f : embedded_sequence_scenes())
            if (f.path == name + ".json" && !(quick && !out.empty())) out.push_back({name, "", std::string(f.text)});
    return out;
}

// A scene ready to fly: its pack, compiled once, and its CPU twin (which reads the IR it was made from).
struct Scene {
    std::string name;
    Pack pack;
    std::unique_ptr<IrGraph> ir;
    std::optional<CpuEvaluator> twin;
};

std::optional<Scene> load_scene(const SceneSource& source, Diagnostics& diag) {
    std::optional<Pack> pack;
    if (std::filesystem::path(source.path).extension() == ".fgpack") {
        pack = read_pack_file(source.path, diag);
    } else {
        std::string text = source.graph_text;
        if (!source.path.empty()) {
            std::ifstream in(source.path, std::ios::binary);
            if (!in) {
                diag.error(fmt::format("cannot read {}", source.path));
                return std::nullopt;
            }
            text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        auto compiled = compile_graph(text, NodeLibrary::builtin(), {}, diag);
        if (compiled) pack = read_pack(pack_bytes(*compiled), diag);
    }
    if (!pack) return std::nullopt;
    auto ir = load_and_lower(pack->graph, NodeLibrary::builtin(), diag);
    if (!ir) return std::nullopt;
    Scene scene{source.name, std::move(*pack), std::make_unique<IrGraph>(std::move(*ir)), std::nullopt};
    scene.twin = CpuEvaluator::create(*scene.ir, diag);   // the traces need it: a scene without one is refused
    if (!scene.twin) return std::nullopt;
    return scene;
}

// The strict reference of one frame (its depths judge the march), and the picture's ground truth:
// 16 jittered samples per pixel of naive tracing at the output detail. Empty for a dark frame.
struct ReferenceFrame {
    Rgba8Image left, right;
    std::vector<double> depth_left, depth_right;
    Rgba8Image truth_left, truth_right;
};

constexpr std::uint32_t kTruthSamples = 16;

// The naive tracer at the pack's own knobs: what the picture's ground truth averages.
FrameSettings truth_settings(std::uint32_t size) {
    FrameSettings f;
    f.width = f.height = size;
    f.stereo = StereoMode::Naive;
    f.foveation = 0.0;
    return f;
}

// A snap turn's fade as `fgplay xr` applies it: the last pass scales the image.
void set_brightness(HeadlessRenderer& renderer, const GpuScene& scene, double brightness) {
    GpuScene faded = scene;
    faded.fade = static_cast<float>(1.0 - brightness);
    renderer.executor().set_scene(faded);
}

// The renderers of one setting, kept for the whole scene, and the pixels its viewer sees.
struct SettingRenderers {
    std::unique_ptr<HeadlessRenderer> timed, counting;
    std::vector<std::uint8_t> seen_left, seen_right;   // empty: every pixel (no lens mask)
    // ... of the output image where it is larger than the marched one (temporal upsampling).
    std::vector<std::uint8_t> shown_left, shown_right;
    // The last frame compared, for flicker: its images and its index in the trace.
    Rgba8Image last_left, last_right;
    std::size_t last_index = static_cast<std::size_t>(-1);

    SettingRenderers(const vk::Context& ctx, const Pack& pack, const FrameSettings& frame,
                     const StereoSettings& stereo) {
        timed = std::make_unique<HeadlessRenderer>(ctx, pack, frame, stereo);
        FrameSettings counted = frame;
        counted.count_evaluations = true;
        counting = std::make_unique<HeadlessRenderer>(ctx, pack, counted, stereo);
        if (frame.lens_mask) {
            const StereoViews& v = timed->views();
            seen_left = visible_pixels(lens_ellipse(v.left), v.left.width, v.left.height);
            seen_right = visible_pixels(lens_ellipse(v.right), v.right.width, v.right.height);
            const FrameGraph& g = timed->graph();
            shown_left = visible_pixels(lens_ellipse(v.left), g.output_width, g.output_height);
            shown_right = visible_pixels(lens_ellipse(v.right), g.output_width, g.output_height);
        }
    }
};

// The pixels an eye sees (`seen`, empty for all) that it also marched itself (not foveation's fill).
std::vector<std::uint8_t> seen_and_marched(const std::vector<std::uint8_t>& seen, const GpuFrame& frame, int view) {
    std::vector<std::uint8_t> mask = marched_pixels(frame, view);
    for (std::size_t i = 0; i < seen.size(); ++i) mask[i] &= seen[i];
    return mask;
}

// The pictures against the strict reference's and the ground truth's; `before`: the references of
// frame index - 1, where it was compared too (for flicker).
void compare_pictures(const RenderedFrame& frame, std::size_t index, const ReferenceFrame& ref,
                      const ReferenceFrame* before, SettingRenderers& r, SequenceFrame& out) {
    const auto& seen_left = r.shown_left.empty() ? r.seen_left : r.shown_left;
    const auto& seen_right = r.shown_right.empty() ? r.seen_right : r.shown_right;
    out.psnr = 0.5 * (psnr(frame.left, ref.left, seen_left) + psnr(frame.right, ref.right, seen_right));
    out.picture_psnr = 0.5 * (psnr(frame.left, ref.truth_left, seen_left) + psnr(frame.right, ref.truth_right, seen_right));
    if (before && r.last_index + 1 == index)
        out.flicker = 0.5 * (flicker(frame.left, r.last_left, ref.truth_left, before->truth_left, seen_left) +
                             flicker(frame.right, r.last_right, ref.truth_right, before->truth_right, seen_right));
    r.last_left = frame.left;
    r.last_right = frame.right;
    r.last_index = index;
    out.compared = true;
}

// The frame's depths against the strict reference's, then its pictures (compare_pictures).
void compare(const RenderedFrame& frame, std::size_t index, const ReferenceFrame& ref, const ReferenceFrame* before,
             double pixel_half_diagonal, SettingRenderers& r, SequenceFrame& out) {
    compare_pictures(frame, index, ref, before, r, out);
    // Temporal upsampling marches fewer pixels than the reference: its depths are not compared.
    if (frame.depth_left.size() != ref.depth_left.size()) return;
    DepthComparison left = compare_depths(frame.depth_left, ref.depth_left, pixel_half_diagonal, r.seen_left);
    DepthComparison right = compare_depths(frame.depth_right, ref.depth_right, pixel_half_diagonal, r.seen_right);
    const double pixels = static_cast<double>(std::max<std::size_t>(1, left.pixels + right.pixels));
    out.misclassified_pct = 50.0 * (left.misclassified + right.misclassified);
    out.overstepped_pct = 100.0 * static_cast<double>(left.overstepped + right.overstepped) / pixels;
    // The same oversteps, counted only where the march set the depth: foveation's fill copies a
    // neighbour's, which can lie behind this pixel's surface whatever the march did.
    const GpuFrame& uniforms = r.timed->executor().frame();
    std::size_t marched_oversteps = left.overstepped + right.overstepped;
    if (uniforms.fovea_radius > 0.0f) {
        marched_oversteps =
            compare_depths(frame.depth_left, ref.depth_left, pixel_half_diagonal,
                           seen_and_marched(r.seen_left, uniforms, kLeftView)).overstepped +
            compare_depths(frame.depth_right, ref.depth_right, pixel_half_diagonal,
                           seen_and_marched(r.seen_right, uniforms, kRightView)).overstepped;
    }
    out.overstepped_march_pct = 100.0 * static_cast<double>(marched_oversteps) / pixels;
    out.not_finite = left.not_finite + right.not_finite;
    out.depths_compared = true;
}

// Before a trace: the trace's world scale, and one untimed frame on each renderer so pipelines and
// caches are warm and a setting that reuses the frame before starts both renderers with one history.
void warm_up(SettingRenderers& r, const HeadTrace& trace, const GpuScene& scene) {
    const TraceFrame& first = trace.frames.front();
    for (HeadlessRenderer* renderer : {r.timed.get(), r.counting.get()}) {
        renderer->set_world_scale(trace.world_scale);
        set_brightness(*renderer, scene, 1.0);
        renderer->run(first.head, first.time, 0);
    }
}

// Trace frame `i` on `renderer`: read back into `image` where one is given, else only its stats.
FrameStats render_or_run(HeadlessRenderer& renderer, const TraceFrame& tf, std::size_t i, RenderedFrame* image) {
    const auto index = static_cast<std::uint32_t>(i);
    if (!image) return renderer.run(tf.head, tf.time, index);
    *image = renderer.render(tf.head, tf.time, index);
    return image->stats;
}

// Frame `i` of a trace on a setting's timed renderer: its GPU times, and where `image` is given the
// frame read back into it. A dark frame renders nothing, as on a headset.
SequenceFrame time_frame(SettingRenderers& r, const HeadTrace& trace, std::size_t i, const GpuScene& scene,
                         const GpuClock* clock, RenderedFrame* image) {
    const TraceFrame& tf = trace.frames[i];
    SequenceFrame f;
    f.index = static_cast<int>(i);
    f.dark = tf.brightness <= 0.0;
    if (f.dark) return f;
    set_brightness(*r.timed, scene, tf.brightness);
    const FrameStats stats = render_or_run(*r.timed, tf, i, image);
    if (auto mhz = clock ? clock->sm_mhz() : std::nullopt) f.sm_clock_mhz = *mhz;
    f.gpu_ms = stats.gpu_ms.count("frame") ? stats.gpu_ms.at("frame") : 0.0;
    for (const char* pass : {"shade", "fovea"})
        if (auto it = stats.gpu_ms.find(pass); it != stats.gpu_ms.end()) f.after_march_ms += it->second;
    return f;
}

// Frame `i` on a setting's counting renderer (bit-identical frames, PersistentLanes test); its counts go
// into `f` and `row` where `counts_now`, and where `image` is given the frame is read back into it.
void count_frame(SettingRenderers& r, const HeadTrace& trace, std::size_t i, const GpuScene& scene, bool counts_now,
                 SequenceFrame& f, SequenceRow& row, RenderedFrame* image) {
    const TraceFrame& tf = trace.frames[i];
    set_brightness(*r.counting, scene, tf.brightness);
    const FrameStats counted = render_or_run(*r.counting, tf, i, image);
    if (!counts_now) return;
    if (auto it = counted.reuse_skipped.find("march.L0"); it != counted.reuse_skipped.end())
        row.reuse_skipped_sum += it->second, ++row.reuse_skipped_frames;
    f.evaluations_per_pixel = counted.evaluations_per_pixel;
    f.iterations_per_pixel = counted.iterations_per_pixel;
    if (row.counter_groups.empty())
        for (const auto& [group, _] : counted.evaluations) row.counter_groups.push_back(group);
    for (const auto& [group, lanes] : counted.lanes) {
        row.lanes[group].busy += lanes.busy;
        row.lanes[group].total += lanes.total;
    }
}

// Interleaved (a CPU device's default): frame `i` timed, read back and compared where `ref` is given,
// then counted every `count_every` frames. A setting that reuses the frame before (cross-frame reuse,
// temporal anti-aliasing, whose jitter follows its history) renders every frame on the counting
// renderer too, so that its history is the timed one's.
void render_frame(SettingRenderers& r, const HeadTrace& trace, std::size_t i, const ReferenceFrame* ref,
                  const ReferenceFrame* before, double pixel_half_diagonal, const GpuScene& scene, const GpuClock* clock,
                  int count_every, SequenceRow& row) {
    RenderedFrame frame;
    SequenceFrame f = time_frame(r, trace, i, scene, clock, ref ? &frame : nullptr);
    if (!f.dark) {
        if (ref) compare(frame, i, *ref, before, pixel_half_diagonal, r, f);
        const bool counts_now = i % static_cast<std::size_t>(count_every) == 0;
        const FrameGraph& counted = r.counting->executor().graph();
        if (counts_now || counted.reuse || counted.taa)
            count_frame(r, trace, i, scene, counts_now, f, row, nullptr);
    }
    row.frames.push_back(f);
}

// Back to back (a GPU's default), after the trace's timed frames: frame `i` again on the counting renderer,
// which renders every frame in order (so a reusing setting's history is the timed one's), read back and
// compared where `ref` is given, its counts taken every `count_every` frames.
void measure_frame(SettingRenderers& r, const HeadTrace& trace, std::size_t i, const ReferenceFrame* ref,
                   const ReferenceFrame* before, double pixel_half_diagonal, const GpuScene& scene, int count_every,
                   SequenceRow& row) {
    SequenceFrame& f = row.frames.at(i);
    if (f.dark) return;
    RenderedFrame frame;
    count_frame(r, trace, i, scene, i % static_cast<std::size_t>(count_every) == 0, f, row, ref ? &frame : nullptr);
    if (ref) compare(frame, i, *ref, before, pixel_half_diagonal, r, f);
}

double load_average() {
    double one_minute = -1.0;
    return getloadavg(&one_minute, 1) == 1 ? one_minute : -1.0;
}

std::string minutes(double seconds) {
    return seconds < 90.0 ? fmt::format("{:.0f} s", seconds) : fmt::format("{:.0f} min", seconds / 60.0);
}

}  // namespace

int run_sequence_bench(const BenchOptions& o) {
    // Mesa caches compiled pipelines on disk; a benchmark must not time a warm cache one run and
    // a cold one the next.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    const std::uint32_t size = o.size ? o.size : (o.quick ? 64 : 512);
    const int frames = o.frames ? o.frames : (o.quick ? 12 : 90);
    const int count_every = o.quick ? kQuickCountEvery : kCountEvery;
    const auto& known = head_trace_names();
    for (const auto& t : o.traces)
        if (std::find(known.begin(), known.end(), t) == known.end()) {
            fmt::print(stderr, "fgplay bench --sequence: no trace '{}'; the traces are {}\n", t,
                       fmt::join(known, ", "));
            return 2;
        }
    std::vector<SceneSource> scenes;
    for (const auto& given : o.scenes) scenes.push_back({std::filesystem::path(given).stem().string(), given, ""});
    for (const auto& given : {o.pack, o.graph})
        if (!given.empty()) scenes.push_back({std::filesystem::path(given).stem().string(), given, ""});
    if (scenes.empty()) scenes = default_scenes(o.quick);
    const std::vector<std::string> wanted = o.traces.empty() ? known : o.traces;
    std::filesystem::create_directories(o.out);

    vk::ContextOptions ctx_options;
    ctx_options.device = o.device;
    ctx_options.require_timestamps = false;
    vk::Context ctx(ctx_options);
    std::vector<SequenceVariant> variants(o.variants.size());
    for (std::size_t i = 0; i < o.variants.size(); ++i) {
        std::string error;
        if (!parse_sequence_variant(o.variants[i], variants[i], error)) {
            fmt::print(stderr, "fgplay bench --sequence: {}\n", error);
            return 2;
        }
    }
    const auto settings = make_sequence_settings(size, o.quick, variants);
    SequenceReport report;
    report.device = ctx.device_name();
    // A GPU whose frames alternate with readbacks and comparisons looks idle to its driver, which
    // lowers its clock (an H100 fell from 1980 to 345 MHz, frame times rising 5.7x): there the timed
    // frames run back to back and the errors and counts come after. A CPU device (lavapipe) has no
    // such clock, and the one pass saves it rendering every frame twice.
    report.back_to_back = o.timing == "auto" ? !ctx.is_cpu_device() : o.timing == "back-to-back";
    const auto clock = GpuClock::find(ctx.device_name());
    report.max_sm_mhz = clock ? clock->max_sm_mhz() : 0;
    report.compare_every = std::max(1, o.compare_every);
    report.size = size;
    report.frames = frames;
    report.count_every = count_every;
    report.load_start = load_average();
    fmt::print(
        "sequence benchmark on {}: {} scenes x {} traces x {} settings, {}x{} per eye, {} frames per trace at "
        "{:g} Hz\n",
        ctx.device_summary(), scenes.size(), wanted.size(), settings.size(), size, size, frames, kHeadsetHz);
    if (!ctx.timestamps_supported()) fmt::print("note: no GPU timestamps on this device; times are missing\n");

    // Every scene compiled before the first frame: a graph with an error fails now, not an hour in.
    std::vector<Scene> loaded;
    for (const auto& source : scenes) {
        Diagnostics diag;
        auto scene = load_scene(source, diag);
        if (!scene) {
            fmt::print(stderr, "{}", diag.format(source.path.empty() ? source.name : source.path));
            return 1;
        }
        loaded.push_back(std::move(*scene));
    }

    // Work is counted in trace frames: each one rendered by the reference and by every setting.
    const std::size_t total = loaded.size() * wanted.size() * static_cast<std::size_t>(frames);
    std::size_t done = 0;
    const auto started = std::chrono::steady_clock::now();
    auto elapsed_s = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
    auto time_left = [&] {
        return minutes(elapsed_s() / static_cast<double>(done) * static_cast<double>(total - done));
    };
    for (const Scene& scene : loaded) {
        SceneSettings scene_settings = scene.ir->scene;
        HeadPose start{};
        for (const auto& v : make_bench_views(*scene.twin, scene_settings))
            if (v.name == "filled") start = v.head;
        auto traces = make_head_traces(*scene.twin, scene_settings, start, frames);
        std::erase_if(traces, [&](const HeadTrace& t) {
            return std::find(wanted.begin(), wanted.end(), t.name) == wanted.end();
        });
        if (report.traces.empty())
            for (const auto& t : traces) report.traces.emplace_back(t.name, t.motion);

        StereoSettings stereo;
        stereo.world_scale = scene_settings.world_scale;
        const GpuScene gpu_scene = make_gpu_scene(scene.pack.manifest.scene);
        HeadlessRenderer reference(ctx, scene.pack, strict_reference_settings(scene.pack.manifest, size, size), stereo);
        HeadlessRenderer truth(ctx, scene.pack, truth_settings(size), stereo);
        const double half_diagonal = reference.views().pixel_half_diagonal;
        std::vector<std::unique_ptr<SettingRenderers>> renderers(settings.size());
        std::vector<std::string> broken(settings.size());   // why a setting's renderers could not be made
        for (std::size_t s = 0; s < settings.size(); ++s) {
            try {
                renderers[s] = std::make_unique<SettingRenderers>(ctx, scene.pack, settings[s].frame, stereo);
            } catch (const std::exception& e) {
                broken[s] = e.what();
            }
        }
        for (const auto& trace : traces) {
            const double ref_started = elapsed_s();
            reference.set_world_scale(trace.world_scale);
            truth.set_world_scale(trace.world_scale);
            // Only the frames compared (every one unless --compare-every): at a headset's size each
            // reference frame holds tens of megabytes.
            auto compared = [&](std::size_t i) { return i % static_cast<std::size_t>(report.compare_every) == 0; };
            std::vector<ReferenceFrame> refs(trace.frames.size());
            for (std::size_t i = 0; i < trace.frames.size(); ++i) {
                const TraceFrame& tf = trace.frames[i];
                if (tf.brightness <= 0.0 || !compared(i)) continue;
                set_brightness(reference, gpu_scene, tf.brightness);
                RenderedFrame frame = reference.render(tf.head, tf.time, static_cast<std::uint32_t>(i));
                set_brightness(truth, gpu_scene, tf.brightness);
                RenderedFrame picture = render_samples(truth, tf.head, tf.time, static_cast<std::uint32_t>(i), kTruthSamples);
                refs[i] = {std::move(frame.left), std::move(frame.right),
                           std::vector<double>(frame.depth_left.begin(), frame.depth_left.end()),
                           std::vector<double>(frame.depth_right.begin(), frame.depth_right.end()),
                           std::move(picture.left), std::move(picture.right)};
            }
            const ReferenceFrame& first = refs.front();
            const auto last =
                std::find_if(refs.rbegin(), refs.rend(), [](const ReferenceFrame& f) { return !f.left.pixels.empty(); });
            if (!first.left.pixels.empty() && last != refs.rend())
                write_png(
                    (std::filesystem::path(o.out) / fmt::format("trace_{}_{}.png", scene.name, trace.name)).string(),
                    side_by_side(first.left, last->left));
            fmt::print("{} {}: reference of {} frames in {}\n", scene.name, trace.name, trace.frames.size(),
                       minutes(elapsed_s() - ref_started));

            std::vector<SequenceRow> rows(settings.size());
            for (std::size_t s = 0; s < settings.size(); ++s) {
                rows[s].scene = scene.name;
                rows[s].trace = trace.name;
                rows[s].setting = settings[s];
                rows[s].error = broken[s];
            }
            // A setting that fails stops there; the others go on.
            auto attempt = [&](std::size_t s, const std::function<void()>& work) {
                if (!rows[s].error.empty()) return;
                try {
                    work();
                } catch (const std::exception& e) {
                    rows[s].error = e.what();
                }
            };
            for (std::size_t s = 0; s < settings.size(); ++s)
                attempt(s, [&] { warm_up(*renderers[s], trace, gpu_scene); });
            // Each frame goes through every setting before the next frame, starting with another setting
            // each time: a slow spell of a shared machine falls on all settings alike, not on whichever ran
            // then. Each renderer still renders the trace's frames in order.
            auto each_setting = [&](std::size_t i, const std::function<void(std::size_t)>& work) {
                for (std::size_t k = 0; k < settings.size(); ++k) {
                    const std::size_t s = (i + k) % settings.size();
                    attempt(s, [&] { work(s); });
                }
            };
            if (report.back_to_back) {
                const TraceFrame& first_frame = trace.frames.front();
                raise_gpu_clock(ctx, clock.get(), [&] { reference.run(first_frame.head, first_frame.time, 0); });
                for (std::size_t i = 0; i < trace.frames.size(); ++i)
                    each_setting(i, [&](std::size_t s) {
                        rows[s].frames.push_back(time_frame(*renderers[s], trace, i, gpu_scene, clock.get(), nullptr));
                    });
            }
            for (std::size_t i = 0; i < trace.frames.size(); ++i) {
                const ReferenceFrame* ref = compared(i) ? &refs[i] : nullptr;
                const ReferenceFrame* before = i > 0 && compared(i - 1) && !refs[i - 1].truth_left.pixels.empty() ? &refs[i - 1] : nullptr;
                each_setting(i, [&](std::size_t s) {
                    if (report.back_to_back)
                        measure_frame(*renderers[s], trace, i, ref, before, half_diagonal, gpu_scene, count_every, rows[s]);
                    else
                        render_frame(*renderers[s], trace, i, ref, before, half_diagonal, gpu_scene, clock.get(),
                                     count_every, rows[s]);
                });
                ++done;
                if ((i + 1) % 15 == 0 && i + 1 < trace.frames.size()) {
                    fmt::print("{} {}: frame {}/{}  (about {} left)\n", scene.name, trace.name, i + 1,
                               trace.frames.size(), time_left());
                    std::fflush(stdout);   // progress, even into a pipe or a log file
                }
            }
            for (auto& row : rows) {
                row.summarize();
                fmt::print("{:<10} {:<11} {:<50} {}  (about {} left)\n", scene.name, trace.name, row.setting.name(),
                           row.error.empty() ? row.brief() : "error: " + row.error, time_left());
                report.rows.push_back(std::move(row));
            }
            std::fflush(stdout);
        }
    }
    report.wall_s = elapsed_s();
    report.load_end = load_average();
    report.fill_speedups();
    report.write(o.out);
    if (o.plots) report.plot(o.out);
    fmt::print("results: {}/sequence.md, sequence.csv, sequence_frames.csv ({})\n", o.out, minutes(report.wall_s));
    fmt::print("{}", report.headline());
    return 0;
}

}  // namespace fg::bench
