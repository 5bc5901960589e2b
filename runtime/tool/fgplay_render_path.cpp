// `fgplay render P.fgpack --path camera.json --frames A:B --out DIR`: a camera path to numbered
// images, resumable and shardable for job arrays (docs/scale-out.md).
#include <fmt/format.h>

#include "command_outcome.h"
#include "fgplay_render.h"
#include "offline/frame_record.h"
#include "offline/path_params.h"
#include "offline/path_render.h"
#include "pack/pack_reader.h"
#include "vk/context.h"

namespace fg::fgplay {

namespace {
// The job's fingerprint: a frame record from another pack, path or settings does not count.
std::string job_fingerprint(const RenderOptions& o, const PathRenderSettings& s) {
    std::uint64_t pack = 0, path = 0;
    hash_file(o.pack, pack);
    hash_file(o.path, path);
    return fmt::format("pack {} path {} {}", hex64(pack), hex64(path), settings_fingerprint(s));
}
}  // namespace

int render_path(const RenderOptions& o) {
    auto pack = read_pack_or_report(o.pack);
    if (!pack) return 1;
    Diagnostics diag;
    auto path = CameraPath::load(o.path, pack->manifest.scene.world_scale, diag);
    if (!path || !check_path_params(*path, pack->manifest, diag)) {
        fmt::print(stderr, "{}", diag.format(o.path));
        return 1;
    }
    std::string error;
    auto range = parse_frame_range(o.frame_range, path->frame_count(), error);
    if (!range) {
        fmt::print(stderr, "fgplay: {}\n", error);
        return 2;
    }
    if (o.taa && (!o.shard.empty() || o.resume)) {
        // Each frame blends the ones before it: a shard or a resumed run would start without them.
        fmt::print(stderr, "fgplay: --taa carries history from frame to frame: render the range in one run, without "
                           "--shard or --resume\n");
        return 2;
    }
    if (!o.shard.empty()) {
        int index = 0, count = 1;
        if (!parse_shard(o.shard, index, count, error)) {
            fmt::print(stderr, "fgplay: {}\n", error);
            return 2;
        }
        *range = shard_of(*range, index, count);
    }
    PathRenderSettings s;
    s.projection = o.projection;
    s.stereo = o.stereo;
    s.width = o.width;
    s.height = o.height;
    s.supersample = o.supersample;
    s.samples = o.samples;
    s.noise = o.noise;
    s.min_samples = o.min_samples;
    s.detail = o.detail;
    s.taa = o.taa;
    s.taa_upscale = o.taa_upscale;
    s.taa_sharpen = o.taa_sharpen;
    s.aperture = o.aperture;
    s.focus = o.focus;
    s.shutter = o.shutter;
    s.cone_levels = o.cone_levels;
    s.ipd_m = o.ipd_m;
    s.knobs = o.knobs;
    s.count_evaluations = o.count;
    s.format = o.format;
    s.compression = o.compression;
    return run_reporting_errors([&] {
        vk::Context ctx(render_context_options(o.validation, o.device));
        PathRenderer renderer(ctx, *pack, *path, s);
        if (o.describe) fmt::print("{}", renderer.describe());
        fmt::print("device: {}\n{} frames {}:{} of {} ({:.3g} fps path), {} {}x{} per eye, supersampling {}, {} samples, {}\n",
                   ctx.device_name(), range->size(), range->begin, range->end, path->frame_count(), path->fps(),
                   projection_name(s.projection), s.width, s.height, s.supersample, s.samples,
                   output_format_name(s.format));
        std::fflush(stdout);
        PathRun run{o.out, *range, job_fingerprint(o, s), o.resume, o.progress};
        PathRunResult result = run_path(renderer, run);
        double fps = result.rendered > 0 ? result.rendered / result.seconds : 0.0;
        fmt::print("rendered {} frames, skipped {} already done, in {:.1f} s: {:.3f} frames/s, {:.0f} frames/hour\n",
                   result.rendered, result.skipped, result.seconds, fps, 3600.0 * fps);
        if (result.rendered > 0)
            fmt::print("encoding and writing: {:.3f} s per frame (beside the next frame's rendering)\n",
                       result.write_seconds / result.rendered);
        if (s.count_evaluations && result.rendered > 0)
            fmt::print("SDF evaluations per sample: {:.2f} (mean over the rendered frames)\n", result.evaluations_per_sample);
        if (validation_failed(ctx)) return 1;
        return 0;
    });
}

}  // namespace fg::fgplay
