#include "render_command.h"

#include <cstdio>
#include <fmt/format.h>

#include "frame/frame_arguments.h"
#include "offline/jittered_samples.h"

namespace fg::fgplay {

void add_render_command(CLI::App& app, RenderCommand& c) {
    RenderOptions& r = c.options;
    CLI::App* render = c.command =
        app.add_subcommand("render", "render a stereo frame headless (Mesa lavapipe without a GPU)");
    render->add_option("pack", r.pack, "shader pack")->required()->check(CLI::ExistingFile);
    render->add_option("--out", r.out, "output folder")->capture_default_str();
    render->add_option("--size", c.size, "per-eye size WxH")->capture_default_str();
    render->add_option("--ipd", r.ipd_m, "interpupillary distance in metres")->capture_default_str();
    render->add_option("--camera", c.camera, "camera position and target: px,py,pz,tx,ty,tz");
    render->add_option("--stereo", c.stereo, "reproject | per-eye | naive")->capture_default_str();
    render->add_flag("--naive", c.naive, "the baseline: naive per-eye sphere tracing (same as --stereo naive)");
    render->add_option("--levels", r.cone_levels, "conemarch levels, full resolution included")->capture_default_str();
    render->add_option("--frames", c.frames, "frames to render (numbered images when more than one); with --path a range A:B");
    render->add_option("--path", r.path, "render a camera path (docs/camera-path.md) to DIR/frame_NNNNNN.png")->check(CLI::ExistingFile);
    render->add_option("--projection", c.projection, "with --path: perspective | equirect | ods")->capture_default_str();
    render->add_option("--supersample", r.supersample, "with --path: samples per pixel along each axis (1-8)")->capture_default_str();
    render->add_option("--samples", r.samples,
                       "jittered samples per pixel, averaged in linear light: the --supersample picture of as many "
                       "samples in the memory of one frame")
        ->capture_default_str()
        ->check(CLI::Range(1u, kMaxSamples));
    render->add_option("--noise", r.noise,
                       "adaptive sampling (with --samples N, the most a pixel takes): a pixel stops once the noise of its "
                       "mean is below this, in display units (0.004 is one step of an 8-bit value); the march and the "
                       "shading then skip its 8x8 tile")
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--min-samples", r.min_samples, "with --noise: samples every pixel takes before it may stop")
        ->capture_default_str()
        ->check(CLI::Range(2u, kMaxSamples));
    render->add_option("--detail", r.detail,
                       "detail level: the hit threshold and normal taps are 1/D of an output pixel, at any sampling "
                       "(2: finer detail, slower; 0.5: coarser, faster)")
        ->capture_default_str()
        ->check(CLI::Range(0.125, 8.0));
    render->add_flag("--taa", r.taa,
                     "temporal anti-aliasing as a headset runs it: jittered rays every frame, blended into a history "
                     "per eye (static scenes; the frames of --frames N or --path carry it from one to the next)");
    render->add_option("--taa-upscale", r.taa_upscale,
                       "temporal upsampling (with --taa): march 1/F of the size per axis and resolve to the full size "
                       "(1.5 or 2: fewer rays, softer under motion; a still view refines to 16 samples per pixel)")
        ->capture_default_str()
        ->check(CLI::Range(1.0, 2.0));
    render->add_option("--taa-sharpen", r.taa_sharpen,
                       "with --taa: how much the shown picture sharpens history moving less than a pixel a frame, "
                       "which each frame's resampling blurs (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--aperture", r.aperture,
                       "depth of field (with --samples): the thin lens's diameter in scene units; 0 is a pinhole")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    render->add_option("--focus", r.focus,
                       "with --aperture: the distance in scene units that stays sharp (default: what the view's centre "
                       "sees, each frame)")
        ->check(CLI::PositiveNumber);
    render->add_option("--shutter", r.shutter,
                       "with --path and --samples: motion blur, the shutter open for this share of each frame's "
                       "interval (0.5 is a film camera's 180 degrees); each sample looks from its moment of the path")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    render->add_option("--format", c.format,
                       "with --path: png | png16 (16-bit, from the HDR beauty) | exr (OpenEXR with the beauty and "
                       "passes for compositing)")
        ->capture_default_str();
    render->add_option("--exr-compression", c.compression, "with --format exr: zip | piz | none")->capture_default_str();
    render->add_option("--shard", r.shard, "with --path: I/N, render shard I of N of the frame range (a job array's index)");
    render->add_flag("--resume", r.resume, "with --path: skip frames already on disk and verified");
    render->add_flag("!--no-progress", r.progress, "no progress bar on stderr (paths, and stills of --samples N)");
    render->add_option("--time", r.time, "scene time in seconds of the first frame");
    render->add_option("--knob", c.knobs, "override an accuracy knob: name=value (fgc info lists them)");
    render->add_flag("--describe", r.describe, "print the frame graph: passes, images, sizes");
    render->add_flag("--time-passes", r.time_passes,
                     "GPU time of each pass instead of each pass group, with counting off, after an untimed warm-up frame "
                     "(on a CPU device a timestamp around every pass slows the frame: take frame totals from fgplay "
                     "bench)");
    render->add_flag("--count", r.count,
                     "also count SDF evaluations, fractal iterations and busy SIMD lanes per pass and print them "
                     "(with --path: evaluations per sample); counting costs 5-10 % of the GPU time");
    render->add_flag("--depth", r.depth, "also write 16-bit depth PNGs");
    render->add_flag("--validation", r.validation, "enable the Vulkan validation layer; errors fail the run");
    render->add_option("--device", r.device, "Vulkan device: index or name substring");
    render->add_flag("--lens-mask", r.lens_mask, "skip the pixels a headset's lens hides (an inscribed ellipse)");
    render->add_flag("--whole-dispatch", r.whole_dispatch,
                     "dispatch each pass over its whole image, not the tiles that hold its pixels (to measure what the tiles save)");
    render->add_option("--foveation", r.foveation,
                       "fixed foveation: fovea radius in half image heights (0 off; default: the scene's)")
        ->check(CLI::Range(0.0, 4.0));
}

int RenderCommand::run() {
    RenderOptions& r = options;
    std::string error;
    if (!parse_size(size, 16384, r.width, r.height, error)) {
        fmt::print(stderr, "fgplay: {}\n", error);
        return 2;
    }
    if (!parse_projection(projection, r.projection)) {
        fmt::print(stderr, "fgplay: --projection is perspective, equirect or ods, not '{}'\n", projection);
        return 2;
    }
    if (!parse_output_format(format, r.format)) {
        fmt::print(stderr, "fgplay: --format is png, png16 or exr, not '{}'\n", format);
        return 2;
    }
    if (!parse_exr_compression(compression, r.compression)) {
        fmt::print(stderr, "fgplay: --exr-compression is zip, piz or none, not '{}'\n", compression);
        return 2;
    }
    if (r.path.empty()) {
        if (r.projection != Projection::Perspective || r.resume || !r.shard.empty() || r.supersample != 1 ||
            command->count("--format") || command->count("--exr-compression")) {
            fmt::print(stderr, "fgplay: --projection, --supersample, --format, --shard and --resume go with --path\n");
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
        r.frame_range = command->count("--frames") ? frames : ":";
        // Panoramas are twice as wide as high unless --size says otherwise.
        if (!command->count("--size") && r.projection != Projection::Perspective) r.height = r.width / 2;
    }
    if (naive) stereo = "naive";
    if (!parse_stereo(stereo, r.stereo, error) || !parse_knobs(knobs, r.knobs, error)) {
        fmt::print(stderr, "fgplay: {}\n", error);
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
    return render(r);
}

}  // namespace fg::fgplay
