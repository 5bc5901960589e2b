#include "fgplay_render.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>
#include <vector>
#include <fmt/format.h>

#include "command_outcome.h"
#include "frame/headless_renderer.h"
#include "graph/scene_settings.h"
#include "offline/depth_of_field.h"
#include "offline/jittered_samples.h"
#include "offline/progress_bar.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::fgplay {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// One line per pass, slowest first, with its share of the frame.
void print_pass_times(const std::map<std::string, double>& ms) {
    double frame = ms.count("frame") ? ms.at("frame") : 0.0;
    std::vector<std::pair<double, std::string>> passes;
    for (const auto& [label, t] : ms)
        if (label != "frame") passes.emplace_back(t, label);
    std::sort(passes.rbegin(), passes.rend());
    for (const auto& [t, label] : passes)
        fmt::print("  {:<30} {:8.2f} ms {:5.1f} %\n", label, t, frame > 0.0 ? 100.0 * t / frame : 0.0);
}

}  // namespace

int render(const RenderOptions& o) {
    if (!o.path.empty()) return render_path(o);
    auto pack = read_pack_or_report(o.pack);
    if (!pack) return 1;
    return run_reporting_errors([&] {
        vk::Context ctx(render_context_options(o.validation, o.device));
        FrameSettings frame;
        frame.width = o.width;
        frame.height = o.height;
        frame.stereo = o.stereo;
        frame.cone_levels = o.cone_levels;
        // Counting costs atomics in every step: a pass's own time is taken without it.
        frame.count_evaluations = o.count && !o.time_passes;
        frame.time_each_pass = o.time_passes;
        frame.knobs = o.knobs;
        frame.lens_mask = o.lens_mask;
        frame.foveation = o.foveation;
        frame.tile_dispatch = !o.whole_dispatch;
        frame.detail_scale = 1.0 / o.detail;
        frame.taa = o.taa;
        if (o.taa_upscale > 1.0 && !o.taa) {
            fmt::print(stderr, "fgplay: --taa-upscale resolves through temporal anti-aliasing: add --taa\n");
            return 2;
        }
        set_taa_upscale(frame, o.taa_upscale);
        frame.taa_sharpen = o.taa_sharpen;
        if (o.shutter > 0.0) {
            fmt::print(stderr, "fgplay: --shutter blurs the motion along a camera path: add --path P\n");
            return 2;
        }
        if (o.aperture > 0.0 && (o.samples < 2 || o.taa)) {
            fmt::print(stderr, "fgplay: --aperture blurs by averaging samples through the lens: add --samples N (64 "
                               "for a smooth blur), without --taa\n");
            return 2;
        }
        if (o.noise > 0.0 && (o.samples < 2 || o.whole_dispatch)) {
            fmt::print(stderr, "fgplay: --noise stops converged pixels short of --samples N: add --samples N (the most a "
                               "pixel takes), without --whole-dispatch\n");
            return 2;
        }
        if (o.taa && o.samples > 1) {
            fmt::print(stderr, "fgplay: --taa and --samples both jitter the rays: choose one\n");
            return 2;
        }
        frame.hdr = o.samples > 1;
        const SceneSettings& scene = pack->manifest.scene;
        StereoSettings stereo;
        stereo.ipd_m = o.ipd_m;
        stereo.world_scale = scene.world_scale;
        const auto setup_start = std::chrono::steady_clock::now();
        HeadlessRenderer renderer(ctx, *pack, frame, stereo);
        const double setup_ms = ms_since(setup_start);
        if (o.taa_upscale > 1.0 && !renderer.graph().taa) {
            fmt::print(stderr, "fgplay: --taa-upscale needs temporal anti-aliasing, which this pack cannot have (its scene "
                               "reads time, or it is double precision): render it without\n");
            return 2;
        }
        if (o.describe) fmt::print("{}", renderer.describe());
        HeadPose head = renderer.scene_camera();
        if (o.camera) {
            const auto& c = *o.camera;
            head = look_at({c[0], c[1], c[2]}, {c[3], c[4], c[5]});
        }
        std::filesystem::create_directories(o.out);
        fmt::print("device: {}\n", ctx.device_name());
        // A CPU rasteriser compiles each pipeline at its first dispatch: time the frames after one.
        if (o.time_passes) {
            const auto first_start = std::chrono::steady_clock::now();
            renderer.render(head, o.time, 0);
            // What the pipeline cache saves shows here: the pipelines, and a CPU driver's shader compiles.
            fmt::print("pipelines and images: {:.1f} ms; first frame: {:.1f} ms\n", setup_ms, ms_since(first_start));
        }
        for (int f = 0; f < o.frames; ++f) {
            const double time = o.time + f / 90.0;
            if (o.aperture > 0.0) {
                const double focus = focus_depth_of_field(renderer, o.aperture, o.focus, head, time, static_cast<std::uint32_t>(f));
                fmt::print("depth of field: a lens {:g} wide focused {:.4g} ahead{}\n", o.aperture, focus,
                           o.focus > 0.0 ? "" : " (at the view's centre)");
            }
            SampleBudget budget;
            budget.samples = o.samples;
            budget.noise = o.noise;
            budget.min_samples = o.min_samples;
            std::optional<ProgressBar> bar;
            if (o.samples > 1 && o.progress) bar.emplace(static_cast<int>(o.samples), stderr, "samples");
            double mean_samples = o.samples;
            budget.progress = [&](const SampleProgress& p) {
                mean_samples = p.mean_samples;
                if (!bar) return;
                if (o.noise > 0.0)
                    bar->set_note(fmt::format("{:.0f} % of tiles sampling, {} pixels above the noise target, {:.1f} samples a pixel",
                                              100.0 * p.tiles_sampling, p.noisy_pixels, p.mean_samples));
                bar->advance(false);
            };
            const auto began = std::chrono::steady_clock::now();
            RenderedFrame r = render_samples(renderer, [&](double) { return SampleMoment{head, time}; },
                                             static_cast<std::uint32_t>(f), budget);
            // Beside the GPU's own time: on a GPU, readbacks and summing can be most of a sampled still.
            const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
            if (bar) bar->finish();
            std::string suffix = o.frames > 1 ? fmt::format("_{:04}", f) : "";
            auto path = [&](const std::string& name) { return (std::filesystem::path(o.out) / (name + suffix + ".png")).string(); };
            write_png(path("left"), r.left);
            write_png(path("right"), r.right);
            write_png(path("side_by_side"), side_by_side(r.left, r.right));
            if (o.depth) {
                // The marched depths: upsampling marches fewer pixels than it shows.
                const FrameGraph& g = renderer.graph();
                write_depth_png16(path("depth_left"), r.depth_left, g.width, g.height, static_cast<float>(scene.max_distance));
                write_depth_png16(path("depth_right"), r.depth_right, g.width, g.height, static_cast<float>(scene.max_distance));
            }
            std::string times;
            for (const auto& [group, ms] : r.stats.gpu_ms)
                if (!o.time_passes || group == "frame") times += fmt::format(" {} {:.2f} ms,", group, ms);
            // "march.L0 12.15, march.L1 1.96": a count per pass group, per output pixel of both eyes.
            auto per_pixel = [&](const std::map<std::string, std::uint64_t>& counts) {
                std::string list;
                for (const auto& [group, n] : counts)
                    list += fmt::format("{}{} {:.2f}", list.empty() ? "" : ", ", group, static_cast<double>(n) / (2.0 * o.width * o.height));
                return list;
            };
            std::string samples = o.samples > 1 ? fmt::format(", {} samples summed", o.samples) : "";
            if (o.noise > 0.0) samples = fmt::format(", {:.1f} samples a pixel (at most {}, noise target {:g})", mean_samples, o.samples, o.noise);
            if (renderer.graph().output_width != renderer.graph().width)
                samples += fmt::format(", marched at {}x{}", renderer.graph().width, renderer.graph().height);
            fmt::print("frame {}: {} stereo {}x{} per eye{}; GPU{}{}\n", f, stereo_mode_name(o.stereo), o.width, o.height, samples,
                       times.empty() ? " timestamps unsupported" : times.substr(0, times.size() - 1),
                       o.samples > 1 ? fmt::format("; {:.0f} ms on the clock", wall_ms) : "");
            if (o.time_passes) print_pass_times(r.stats.gpu_ms);
            if (frame.count_evaluations) {
                fmt::print("  SDF evaluations per output pixel: {:.2f} ({})\n", r.stats.evaluations_per_pixel,
                           per_pixel(r.stats.evaluations));
                if (r.stats.iterations_per_pixel > 0.0)
                    fmt::print("  fractal iterations per output pixel: {:.2f} ({})\n", r.stats.iterations_per_pixel,
                               per_pixel(r.stats.iterations));
                std::string lanes;
                for (const auto& [group, count] : r.stats.lanes) lanes += fmt::format(", {} {:.2f}", group, count.efficiency());
                if (!lanes.empty()) fmt::print("  SIMD lanes busy: {}\n", lanes.substr(2));
            }
        }
        if (validation_failed(ctx)) return 1;
        // The names written: numbered when there is more than one frame.
        std::string names;
        for (const char* name : {"left", "right", "side_by_side", "depth_left", "depth_right"})
            if (o.depth || std::string_view(name).substr(0, 5) != "depth")
                names += fmt::format(" {}{}.png", name, o.frames > 1 ? "_NNNN" : "");
        fmt::print("images in {}/:{}{}\n", o.out, names,
                   o.frames > 1 ? fmt::format(" for NNNN from 0000 to {:04}", o.frames - 1) : "");
        return 0;
    });
}

}  // namespace fg::fgplay
