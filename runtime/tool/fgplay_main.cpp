// fgplay: plays Fractograph shader packs. Headless to images (render), benchmarks (bench), a
// desktop window (view) and OpenXR headsets (xr).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench_runner.h"
#include "fgplay_render.h"
#ifdef FG_HAVE_XR
#include "xr/xr_command.h"
#endif
#ifdef FG_HAVE_DESKTOP
#include "desktop/view_command.h"
#endif

int main(int argc, char** argv) {
    CLI::App app{"fgplay: plays Fractograph shader packs (.fgpack)"};
    app.require_subcommand(1);
    fg::fgplay::RenderOptions r;
    std::string size = "512x512", stereo = "per-eye", camera, frames = "1", projection = "perspective";
    std::vector<std::string> knobs;
    bool naive = false;

    auto* render = app.add_subcommand("render", "render a stereo frame headless (Mesa lavapipe without a GPU)");
    render->add_option("pack", r.pack, "shader pack")->required()->check(CLI::ExistingFile);
    render->add_option("--out", r.out, "output folder")->capture_default_str();
    render->add_option("--size", size, "per-eye size WxH")->capture_default_str();
    render->add_option("--ipd", r.ipd_m, "interpupillary distance in metres")->capture_default_str();
    render->add_option("--camera", camera, "camera position and target: px,py,pz,tx,ty,tz");
    render->add_option("--stereo", stereo, "reproject | per-eye | naive")->capture_default_str();
    render->add_flag("--naive", naive, "the baseline: naive per-eye sphere tracing (same as --stereo naive)");
    render->add_option("--levels", r.cone_levels, "conemarch levels, full resolution included")->capture_default_str();
    render->add_option("--frames", frames, "frames to render (numbered images when more than one); with --path a range A:B");
    render->add_option("--path", r.path, "render a camera path (docs/camera-path.md) to DIR/frame_NNNNNN.png")->check(CLI::ExistingFile);
    render->add_option("--projection", projection, "with --path: perspective | equirect | ods")->capture_default_str();
    render->add_option("--supersample", r.supersample, "with --path: samples per pixel along each axis (1-8)")->capture_default_str();
    render->add_option("--shard", r.shard, "with --path: I/N, render shard I of N of the frame range (a job array's index)");
    render->add_flag("--resume", r.resume, "with --path: skip frames already on disk and verified");
    render->add_flag("!--no-progress", r.progress, "with --path: no progress bar on stderr");
    render->add_option("--time", r.time, "scene time in seconds of the first frame");
    render->add_option("--knob", knobs, "override an accuracy knob: name=value (fgc info lists them)");
    render->add_flag("--describe", r.describe, "print the frame graph: passes, images, sizes");
    render->add_flag("--depth", r.depth, "also write 16-bit depth PNGs");
    render->add_flag("--validation", r.validation, "enable the Vulkan validation layer; errors fail the run");
    render->add_option("--device", r.device, "Vulkan device: index or name substring");
    render->add_flag("--lens-mask", r.lens_mask, "skip the pixels a headset's lens hides (an inscribed ellipse)");
    render->add_option("--foveation", r.foveation,
                       "fixed foveation: fovea radius in half image heights (0 off; default: the scene's)")
        ->check(CLI::Range(0.0, 4.0));

    fg::bench::BenchOptions b;
    auto* bench = app.add_subcommand("bench", "accuracy versus time: sweep the knobs, compare with a reference");
    bench->add_option("pack", b.pack, "shader pack (or --graph)");
    bench->add_option("--graph", b.graph, "compile this graph first (and report its compile time)");
    bench->add_option("--compile-gallery", b.gallery, "also report compile time and pack size of every graph in this folder");
    bench->add_option("--out", b.out, "output folder")->capture_default_str();
    bench->add_flag("--quick", b.quick, "a couple of minutes on two cores: 128x128, two views, a few settings");
    bench->add_option("--size", b.size, "per-eye size (default 512, quick 128)");
    bench->add_option("--frames", b.frames, "timed frames per setting (default 3, quick 2)");
    bench->add_option("--view", b.views, "afar, filled, grazing, deep_zoom (repeatable; default all)");
    bench->add_option("--device", b.device, "Vulkan device: index or name substring");
    bool no_plots = false;
    bench->add_flag("--no-plots", no_plots, "skip the matplotlib plots");
    bench->add_flag("--sequence", b.sequence, "head traces at 90 Hz per scene and setting (--frames per trace, default 90)");
    bench->add_option("--trace", b.traces, "with --sequence: look_around, walk, fast_turn, flight, snap_turn (repeatable)");
    bench->add_option("--scene", b.scenes, "with --sequence: a graph or pack (repeatable; default the gallery's bulb, box, Kleinian)");

#ifdef FG_HAVE_XR
    fg::xr::XrCommand xr;
    fg::xr::add_xr_command(app, xr);
#endif
#ifdef FG_HAVE_DESKTOP
    fg::desktop::ViewCommand view;
    fg::desktop::add_view_command(app, view);
#endif

    CLI11_PARSE(app, argc, argv);
#ifdef FG_HAVE_XR
    if (xr.chosen()) return xr.run();
#endif
#ifdef FG_HAVE_DESKTOP
    if (view.chosen()) return view.run();
#endif
    if (*bench) {
        if (!b.sequence && b.pack.empty() == b.graph.empty()) {
            fmt::print(stderr, "fgplay bench: give a pack or --graph, not both\n");
            return 2;
        }
        b.plots = !no_plots;
        return fg::bench::run_bench(b);
    }
    if (*render) {
        unsigned w = 0, h = 0;
        if (std::sscanf(size.c_str(), "%ux%u", &w, &h) != 2 || w == 0 || h == 0 || w > 16384 || h > 16384) {
            fmt::print(stderr, "fgplay: --size must look like 512x512\n");
            return 2;
        }
        r.width = w;
        r.height = h;
        if (!fg::parse_projection(projection, r.projection)) {
            fmt::print(stderr, "fgplay: --projection is perspective, equirect or ods, not '{}'\n", projection);
            return 2;
        }
        if (r.path.empty()) {
            if (r.projection != fg::Projection::Perspective || r.resume || !r.shard.empty() || r.supersample != 1) {
                fmt::print(stderr, "fgplay: --projection, --supersample, --shard and --resume go with --path\n");
                return 2;
            }
            try {
                std::size_t used = 0;
                r.frames = std::stoi(frames, &used);
                if (used != frames.size() || r.frames < 1) throw std::invalid_argument(frames);
            } catch (const std::exception&) {
                fmt::print(stderr, "fgplay: --frames without --path is a count, not '{}'\n", frames);
                return 2;
            }
        } else {
            r.frame_range = render->count("--frames") ? frames : ":";
            // Panoramas are twice as wide as high unless --size says otherwise.
            if (!render->count("--size") && r.projection != fg::Projection::Perspective) r.height = r.width / 2;
        }
        if (naive) stereo = "naive";
        if (!fg::parse_stereo_mode(stereo, r.stereo)) {
            fmt::print(stderr, "fgplay: --stereo is reproject, per-eye or naive, not '{}'\n", stereo);
            return 2;
        }
        if (!camera.empty()) {
            std::array<double, 6> c{};
            if (std::sscanf(camera.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &c[0], &c[1], &c[2], &c[3], &c[4], &c[5]) != 6) {
                fmt::print(stderr, "fgplay: --camera takes px,py,pz,tx,ty,tz\n");
                return 2;
            }
            r.camera = c;
        }
        for (const auto& k : knobs) {
            auto eq = k.find('=');
            try {
                if (eq == std::string::npos) throw std::invalid_argument(k);
                r.knobs[k.substr(0, eq)] = std::stod(k.substr(eq + 1));
            } catch (const std::exception&) {
                fmt::print(stderr, "fgplay: --knob takes name=value, not '{}'\n", k);
                return 2;
            }
        }
        return fg::fgplay::render(r);
    }
    return 2;
}
