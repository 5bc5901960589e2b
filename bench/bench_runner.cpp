#include "bench_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <random>
#include <sstream>

#include "bench_report.h"
#include "bench_settings.h"
#include "bench_views.h"
#include "compiler.h"
#include "frame/accuracy_metrics.h"
#include "frame/cpu_reference_tracer.h"
#include "frame/headless_renderer.h"
#include "frame/lens_mask.h"
#include "frame/strict_reference.h"
#include "frame_measures.h"
#include "gpu_clock.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::bench {

namespace {

struct Reference {
    RenderedFrame frame;
    StereoViews views;
    std::size_t cpu_checked = 0, cpu_disagree = 0;
};

std::optional<std::string> read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Compiles a graph three times: the first compile in a process also initialises glslang.
std::optional<CompileFigure> measure_compile(const std::string& path, std::optional<std::vector<std::uint8_t>>& bytes,
                                             Diagnostics& diag) {
    auto text = read_text(path);
    if (!text) {
        diag.error(fmt::format("cannot read {}", path));
        return std::nullopt;
    }
    std::vector<double> times;
    std::optional<CompileResult> result;
    for (int i = 0; i < 3; ++i) {
        auto start = std::chrono::steady_clock::now();
        result = compile_graph(*text, NodeLibrary::builtin(), {}, diag);
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        if (!result) return std::nullopt;
    }
    bytes = pack_bytes(*result);
    return CompileFigure{path, times.front(), median(times), bytes->size()};
}

}  // namespace

int run_bench(const BenchOptions& o) {
    // Mesa caches compiled pipelines on disk; a benchmark must not time a warm cache one run and
    // a cold one the next.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    std::uint32_t size = o.size ? o.size : (o.quick ? 128 : 512);
    std::filesystem::create_directories(o.out);

    // The pack, compiled here if a graph was given; compile figures for the report.
    Diagnostics diag;
    std::optional<Pack> pack;
    std::vector<CompileFigure> compile_figures;
    if (!o.graph.empty()) {
        std::optional<std::vector<std::uint8_t>> bytes;
        auto figure = measure_compile(o.graph, bytes, diag);
        if (!figure) {
            fmt::print(stderr, "{}", diag.format(o.graph));
            return 1;
        }
        compile_figures.push_back(*figure);
        pack = read_pack(*bytes, diag);
    } else {
        pack = read_pack_file(o.pack, diag);
    }
    if (!pack) {
        fmt::print(stderr, "{}", diag.format(o.pack));
        return 1;
    }
    // The compile side of every gallery graph, for the report.
    if (!o.gallery.empty() && std::filesystem::is_directory(o.gallery)) {
        std::vector<std::filesystem::path> graphs;
        for (const auto& e : std::filesystem::directory_iterator(o.gallery))
            if (e.path().extension() == ".json") graphs.push_back(e.path());
        std::sort(graphs.begin(), graphs.end());
        for (const auto& g : graphs) {
            if (!o.graph.empty() && std::filesystem::equivalent(g, o.graph)) continue;
            Diagnostics ignore;
            std::optional<std::vector<std::uint8_t>> bytes;
            if (auto figure = measure_compile(g.string(), bytes, ignore)) compile_figures.push_back(*figure);
        }
    }

    auto ir = load_and_lower(pack->graph, NodeLibrary::builtin(), diag);
    if (!ir) {
        fmt::print(stderr, "{}", diag.format());
        return 1;
    }
    Diagnostics twin_diag;
    auto twin = CpuEvaluator::create(*ir, twin_diag);
    SceneSettings scene = ir->scene;
    std::vector<BenchView> views;
    if (twin) {
        views = make_bench_views(*twin, scene);
    } else {
        fmt::print("note: {}; benchmarking the scene camera only, without CPU spot checks\n",
                   twin_diag.items().front().message);
        views.push_back({"afar", look_at(scene.camera.position, scene.camera.target, scene.camera.up), scene.world_scale});
    }
    std::vector<std::string> wanted = o.views;
    if (wanted.empty() && o.quick) wanted = {"afar", "filled"};
    if (!wanted.empty())
        std::erase_if(views, [&](const BenchView& v) { return std::find(wanted.begin(), wanted.end(), v.name) == wanted.end(); });

    vk::ContextOptions ctx_options;
    ctx_options.device = o.device;
    ctx_options.require_timestamps = false;
    vk::Context ctx(ctx_options);
    // A GPU renders a frame in milliseconds, and a median of three of them moved by up to 4 % between
    // settings with identical frames on an H100: fifteen there. A CPU device's frames take seconds.
    const int frames = o.frames ? o.frames : (o.quick ? 2 : ctx.is_cpu_device() ? 3 : 15);
    auto settings = make_sweep(pack->manifest, {o.quick, size});
    fmt::print("benchmark: {} on {}, {}x{} per eye, {} views x {} settings, {} timed frames each\n", pack->manifest.name,
               ctx.device_summary(), size, size, views.size(), settings.size(), frames);
    if (!ctx.timestamps_supported()) fmt::print("note: no GPU timestamps on this device; times are missing\n");
    const auto clock = GpuClock::find(ctx.device_name());

    std::vector<BenchRow> rows;
    std::size_t done = 0, total = views.size() * settings.size();
    auto started = std::chrono::steady_clock::now();
    for (const auto& view : views) {
        StereoSettings stereo;
        stereo.world_scale = view.world_scale;
        // A reference per size, and CPU double-precision spot checks of the main one.
        std::map<std::uint32_t, Reference> refs;
        auto reference_for = [&](std::uint32_t sz) -> const Reference& {
            auto it = refs.find(sz);
            if (it != refs.end()) return it->second;
            Reference ref;
            HeadlessRenderer r(ctx, *pack, strict_reference_settings(pack->manifest, sz, sz), stereo);
            ref.frame = r.render(view.head, 0.0);
            ref.views = r.views();
            return refs[sz] = std::move(ref);
        };
        Reference& ref = refs[size] = reference_for(size);
        if (twin) {
            std::mt19937 rng(7);
            ReferenceSettings rs;
            rs.epsilon = 0.05;
            rs.max_steps = 4000;
            rs.step_scale = 0.5 * pack->manifest.find_spec("step_scale")->value;   // as the strict reference
            double cone = std::tan(ref.views.pixel_half_diagonal);
            for (int k = 0; k < 64; ++k) {
                std::uint32_t x = rng() % size, y = rng() % size;
                glm::dvec3 dir = ref.views.left.ray((x + 0.5) / size, (y + 0.5) / size);
                double t = reference_trace(*twin, scene, ref.views.left.origin, dir, cone, rs);
                float g = ref.frame.depth_left[static_cast<std::size_t>(y) * size + x];
                ++ref.cpu_checked;
                bool same_class = (t >= 0.0) == (g >= 0.0f);
                if (!same_class || (t >= 0.0 && std::abs(g - t) > 2.0 * cone * t)) ++ref.cpu_disagree;
            }
        }
        fmt::print("view {}: reference {:.1f} ms, CPU spot checks {}/{} agree\n", view.name,
                   ref.frame.stats.gpu_ms.count("frame") ? ref.frame.stats.gpu_ms.at("frame") : 0.0,
                   ref.cpu_checked - ref.cpu_disagree, ref.cpu_checked);
        write_png((std::filesystem::path(o.out) / fmt::format("reference_{}.png", view.name)).string(),
                  side_by_side(ref.frame.left, ref.frame.right));

        for (const auto& s : settings) {
            BenchRow row;
            row.view = view.name;
            row.setting = s.name;
            row.group = s.group;
            row.baseline = s.baseline;
            row.stereo = stereo_mode_name(s.frame.stereo);
            row.size = s.frame.width;
            row.frame = s.frame;
            row.reference_cpu_checked = ref.cpu_checked;
            row.reference_cpu_disagree = ref.cpu_disagree;
            try {
                // Time with counting off (it costs atomics), then one frame with it on.
                HeadlessRenderer timed(ctx, *pack, s.frame, stereo);
                timed.run(view.head, 0.0);   // warm-up: pipelines, caches
                raise_gpu_clock(ctx, clock.get(), [&] { timed.run(view.head, 0.0); });
                // Back to back: only the last timed frame is read back (a readback leaves a GPU idle).
                RenderedFrame frame;
                std::map<std::string, std::vector<double>> samples;
                for (int f = 0; f < frames; ++f) {
                    if (f + 1 < frames) {
                        frame.stats = timed.run(view.head, 0.0);
                    } else {
                        frame = timed.render(view.head, 0.0);
                    }
                    for (const auto& [group, ms] : frame.stats.gpu_ms) samples[group].push_back(ms);
                }
                for (const auto& [group, v] : samples) row.pass_ms[group] = median(v);
                if (auto mhz = clock ? clock->sm_mhz() : std::nullopt) row.sm_clock_mhz = static_cast<int>(*mhz);
                FrameSettings counting = s.frame;
                counting.count_evaluations = true;
                HeadlessRenderer counted(ctx, *pack, counting, stereo);
                row.evaluations_per_pixel = counted.render(view.head, 0.0).stats.evaluations_per_pixel;
                // Error against the reference of the same size.
                const Reference& same = reference_for(s.frame.width);
                double half_diag = same.views.pixel_half_diagonal;
                auto as_double = [](const std::vector<float>& v) { return std::vector<double>(v.begin(), v.end()); };
                // With the lens mask, error counts only what a viewer sees through the lens.
                std::vector<std::uint8_t> seen_l, seen_r;
                if (s.frame.lens_mask) {
                    seen_l = visible_pixels(lens_ellipse(same.views.left), same.views.left.width, same.views.left.height);
                    seen_r = visible_pixels(lens_ellipse(same.views.right), same.views.right.width, same.views.right.height);
                }
                auto cmp_l = compare_depths(frame.depth_left, as_double(same.frame.depth_left), half_diag, seen_l);
                auto cmp_r = compare_depths(frame.depth_right, as_double(same.frame.depth_right), half_diag, seen_r);
                row.misclassified_pct = 50.0 * (cmp_l.misclassified + cmp_r.misclassified);
                row.depth_median = 0.5 * (cmp_l.median_error + cmp_r.median_error);
                row.depth_p95 = std::max(cmp_l.p95_error, cmp_r.p95_error);
                row.not_finite = cmp_l.not_finite + cmp_r.not_finite;
                row.overstepped = cmp_l.overstepped + cmp_r.overstepped;
                row.psnr = 0.5 * (psnr(frame.left, same.frame.left, seen_l) + psnr(frame.right, same.frame.right, seen_r));
                if (view.name == "filled" || views.size() == 1)
                    write_png((std::filesystem::path(o.out) / fmt::format("{}_{}.png", view.name, file_safe(s.name))).string(),
                              frame.left);
            } catch (const std::exception& e) {
                row.error = e.what();
            }
            rows.push_back(row);
            ++done;
            double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
            fmt::print("[{:>3}/{}] {:<10} {:<44} {}  (about {:.0f} s left)\n", done, total, view.name, s.name,
                       row.error.empty() ? row.brief() : "error: " + row.error, left);
            std::fflush(stdout);   // progress, even into a pipe or a log file
        }
    }
    BenchReport report{pack->manifest.name, ctx.device_name(), size, frames, rows, compile_figures};
    report.max_sm_mhz = clock ? clock->max_sm_mhz() : 0;
    report.fill_ratios();
    report.write(o.out);
    if (o.plots) report.plot(o.out);
    fmt::print("results: {}/results.md, results.csv, time_vs_error.png, time_per_pass.png\n", o.out);
    fmt::print("{}\n", report.summary_line());
    return 0;
}

}  // namespace fg::bench
