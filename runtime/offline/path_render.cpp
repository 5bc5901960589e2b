#include "path_render.h"

#include <chrono>
#include <filesystem>
#include <future>
#include <fmt/format.h>
#include <stdexcept>

#include <stb/stb_image_write.h>

#include "frame_record.h"
#include "jittered_samples.h"
#include "path_params.h"
#include "progress_bar.h"
#include "depth_of_field.h"
#include "supersample.h"

namespace fg {

namespace {

FrameSettings frame_settings(const PathRenderSettings& s) {
    FrameSettings f;
    f.width = s.width * s.supersample;
    f.height = s.height * s.supersample;
    // Every sample hits by the output pixel: the same fractal as 1 spp, only less aliased.
    f.detail_scale = s.supersample / s.detail;
    f.taa = s.taa;
    set_taa_upscale(f, s.taa_upscale);
    f.taa_sharpen = s.taa_sharpen;
    f.stereo = s.stereo;
    f.projection = s.projection;
    f.cone_levels = s.cone_levels;
    f.knobs = s.knobs;
    f.count_evaluations = s.count_evaluations;
    f.aovs = needs_aovs(s.format);
    f.hdr = (s.samples > 1 || s.supersample > 1) && !s.taa;
    // Offline frames are for every part of the image: no lens mask, no foveation.
    f.lens_mask = false;
    f.foveation = 0.0;
    return f;
}

std::vector<std::uint8_t> png_bytes(const Rgba8Image& image) {
    std::vector<std::uint8_t> bytes;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<std::uint8_t>*>(context);
            out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
        },
        &bytes, static_cast<int>(image.width), static_cast<int>(image.height), 4, image.pixels.data(),
        static_cast<int>(image.width * 4));
    return bytes;
}

}  // namespace

std::string settings_fingerprint(const PathRenderSettings& s) {
    std::string knobs;
    for (const auto& [name, value] : s.knobs) knobs += fmt::format("{}={};", name, value);
    // count_evaluations is left out: it changes the work counted, not the pixels.
    std::string format = output_format_name(s.format);
    if (s.format == OutputFormat::Exr) format += std::string("-") + exr_compression_name(s.compression);
    // Written only where they differ from the default, so older records still verify.
    std::string sampling = s.samples > 1 ? fmt::format(" samples{}", s.samples) : "";
    if (s.detail != 1.0) sampling += fmt::format(" detail{}", s.detail);
    if (s.taa) sampling += " taa";
    if (s.taa_upscale > 1.0) sampling += fmt::format(" upscale{}", s.taa_upscale);
    if (s.aperture > 0.0) sampling += fmt::format(" lens{}@{}", s.aperture, s.focus);
    if (s.shutter > 0.0) sampling += fmt::format(" shutter{}", s.shutter);
    return fmt::format("{} {} {}x{} ss{}{} levels{} ipd{} knobs[{}] {}", projection_name(s.projection),
                       stereo_mode_name(s.stereo), s.width, s.height, s.supersample, sampling, s.cone_levels, s.ipd_m,
                       knobs, format);
}

std::string frame_image_path(const std::string& dir, int frame, OutputFormat format) {
    return (std::filesystem::path(dir) / fmt::format("frame_{:06}.{}", frame, output_extension(format))).string();
}

PathRenderer::PathRenderer(const vk::Context& ctx, const Pack& pack, CameraPath path, PathRenderSettings settings)
    : path_(std::move(path)), settings_(std::move(settings)) {
    if (settings_.supersample < 1 || settings_.supersample > 8) throw std::runtime_error("supersampling is 1 to 8");
    if (settings_.samples < 1 || settings_.samples > kMaxSamples)
        throw std::runtime_error(fmt::format("--samples is 1 to {}", kMaxSamples));
    if (settings_.taa && settings_.projection != Projection::Perspective)
        throw std::runtime_error("--taa is for perspective frames, as a headset sees them");
    if (settings_.taa_upscale > 1.0 && (!settings_.taa || settings_.format != OutputFormat::Png))
        throw std::runtime_error("--taa-upscale needs --taa and --format png (the passes of an EXR are the marched size)");
    if (settings_.aperture > 0.0 && (settings_.samples < 2 || settings_.projection != Projection::Perspective))
        throw std::runtime_error("--aperture blurs by averaging --samples N through the lens, in perspective frames");
    if (settings_.shutter > 0.0 && settings_.samples < 2)
        throw std::runtime_error("--shutter blurs by averaging --samples N over the open shutter");
    if (settings_.taa && settings_.samples > 1) throw std::runtime_error("--taa and --samples both jitter the rays: choose one");
    StereoSettings stereo;
    stereo.ipd_m = settings_.ipd_m;
    renderer_ = std::make_unique<HeadlessRenderer>(ctx, pack, frame_settings(settings_), stereo);
    if (settings_.taa_upscale > 1.0 && !renderer_->graph().taa)
        throw std::runtime_error("--taa-upscale needs temporal anti-aliasing, which this pack cannot have (its scene "
                                 "reads time, or it is double precision)");
    Diagnostics diag;
    if (!check_path_params(path_, pack.manifest, diag)) throw std::runtime_error(diag.format("camera path"));
}

void PathRenderer::move_to(const CameraSample& s) {
    renderer_->set_world_scale(s.world_scale);
    // Keyed parameters are uniforms: set before every frame, so each frame depends on its number only.
    FrameExecutor& executor = renderer_->executor();
    for (const auto& [name, value] : s.params)
        if (const ManifestParam* p = executor.manifest().find_param(name)) executor.set_param(name, keyed_param_value(*p, value));
}

OfflineFrame PathRenderer::render_frame(int frame) {
    CameraSample s = path_.sample(frame);
    move_to(s);
    if (settings_.aperture > 0.0)
        focus_depth_of_field(*renderer_, settings_.aperture, settings_.focus, s.head, s.time, static_cast<std::uint32_t>(frame));
    // Motion blur: each sample looks from the path's pose at its moment of the open shutter.
    const double open = path_.keys().front().time + frame / path_.fps();
    auto moment = [&](double u) {
        if (settings_.shutter <= 0.0) return SampleMoment{s.head, s.time};
        CameraSample m = path_.at(open + u * settings_.shutter / path_.fps());
        move_to(m);
        return SampleMoment{m.head, m.time};
    };
    SampleBudget budget;
    budget.samples = settings_.samples;
    budget.noise = settings_.noise;
    budget.min_samples = settings_.min_samples;
    RenderedFrame r = render_samples(*renderer_, moment, static_cast<std::uint32_t>(frame), budget);
    std::uint64_t evaluations = 0;
    for (const auto& [_, n] : r.stats.evaluations) evaluations += n;
    double samples = (is_mono(settings_.projection) ? 1.0 : 2.0) * settings_.width * settings_.height *
                     settings_.supersample * settings_.supersample * settings_.samples;
    last_evaluations_ = static_cast<double>(evaluations) / samples;
    std::uint32_t ss = settings_.supersample;
    // Averaged before the tone map where the frame kept its input (FrameSettings::hdr).
    auto picture = [&](const Rgba8Image& display, const std::vector<float>& hdr) {
        return hdr.empty() ? downsample(display, ss) : display_picture(hdr, display.width, display.height, ss);
    };
    OfflineFrame out;
    switch (settings_.projection) {
        case Projection::Equirect: out.picture = picture(r.left, r.hdr_left); break;
        case Projection::Ods: out.picture = top_bottom(picture(r.left, r.hdr_left), picture(r.right, r.hdr_right)); break;
        case Projection::Perspective:
            out.picture = side_by_side(picture(r.left, r.hdr_left), picture(r.right, r.hdr_right));
            break;
    }
    if (!needs_aovs(settings_.format)) return out;
    const bool perspective = settings_.projection == Projection::Perspective;
    auto eye = [&](const std::string& name, const View& view, std::vector<std::vector<std::byte>>& aovs) {
        OfflineEye e{name, settings_.width, settings_.height, {}, exr_camera(view, s.world_scale, perspective), !perspective};
        // An 8K panorama's AOVs are gigabytes: moved, never copied.
        e.aovs = downsample_aovs(std::move(aovs), settings_.width, settings_.height, ss);
        out.eyes.push_back(std::move(e));
    };
    const StereoViews& views = renderer_->views();
    if (is_mono(settings_.projection)) {
        eye("centre", views.centre, r.aovs_left);
    } else {
        eye("left", views.left, r.aovs_left);
        eye("right", views.right, r.aovs_right);
    }
    return out;
}

std::vector<std::uint8_t> PathRenderer::encode(const OfflineFrame& frame) const {
    switch (settings_.format) {
        case OutputFormat::Png: return png_bytes(frame.picture);
        case OutputFormat::Png16: return encode_png16(frame.eyes, settings_.projection == Projection::Ods);
        case OutputFormat::Exr: break;
    }
    std::vector<ExrPart> parts;
    for (const OfflineEye& e : frame.eyes) parts.push_back({e.view, e.width, e.height, e.aovs, e.camera, e.panorama});
    return encode_exr(parts, settings_.compression);
}

PathRunResult run_path(PathRenderer& renderer, const PathRun& run) {
    std::filesystem::create_directories(run.out_dir);
    PathRunResult result;
    auto start = std::chrono::steady_clock::now();
    std::unique_ptr<ProgressBar> bar;
    if (run.progress) bar = std::make_unique<ProgressBar>(run.frames.size());
    // PNG encoding runs on the CPU at about 6 Mpixel/s: as long as a GPU frame at 8K (OpenEXR's
    // ZIP is slower still). So frame n is encoded and written while frame n + 1 renders; one frame
    // in flight bounds the memory.
    std::future<double> writing;
    auto finish_writing = [&] {
        if (!writing.valid()) return;
        result.write_seconds += writing.get();   // rethrows a failed write
        if (bar) bar->advance(false);
    };
    for (int f = run.frames.begin; f < run.frames.end; ++f) {
        std::string image = frame_image_path(run.out_dir, f, renderer.settings().format);
        if (run.resume && frame_is_done(image, run.job)) {
            ++result.skipped;
            if (bar) bar->advance(true);
            continue;
        }
        OfflineFrame pixels = renderer.render_frame(f);
        ++result.rendered;
        result.evaluations_per_sample += renderer.last_evaluations_per_sample();
        finish_writing();
        writing = std::async(std::launch::async, [pixels = std::move(pixels), image, f, &run, &renderer] {
            auto began = std::chrono::steady_clock::now();
            auto bytes = renderer.encode(pixels);
            if (bytes.empty() || !write_frame_atomically(image, bytes, f, run.job))
                throw std::runtime_error(fmt::format("cannot write {}", image));
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
        });
    }
    finish_writing();
    if (bar) bar->finish();
    if (result.rendered > 0) result.evaluations_per_sample /= result.rendered;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace fg
