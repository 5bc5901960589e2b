#include "jittered_samples.h"

#include <stdexcept>

#include "frame/sample_jitter.h"
#include "offline_image.h"
#include "sample_accumulator.h"

namespace fg {

namespace {

void add_stats(FrameStats& sum, const FrameStats& s) {
    for (const auto& [group, ms] : s.gpu_ms) sum.gpu_ms[group] += ms;
    for (const auto& [group, n] : s.evaluations) sum.evaluations[group] += n;
    for (const auto& [group, n] : s.iterations) sum.iterations[group] += n;
    sum.evaluations_per_pixel += s.evaluations_per_pixel;
    sum.iterations_per_pixel += s.iterations_per_pixel;
}

}  // namespace

RenderedFrame render_samples(HeadlessRenderer& renderer, const HeadPose& head, double time, std::uint32_t frame_index,
                             std::uint32_t samples) {
    if (samples <= 1) return renderer.render(head, time, frame_index);
    return render_samples(renderer, [&](double) { return SampleMoment{head, time}; }, frame_index, samples);
}

RenderedFrame render_samples(HeadlessRenderer& renderer, const std::function<SampleMoment(double)>& moment,
                             std::uint32_t frame_index, std::uint32_t samples) {
    SampleBudget budget;
    budget.samples = samples;
    return render_samples(renderer, moment, frame_index, budget);
}

RenderedFrame render_samples(HeadlessRenderer& renderer, const std::function<SampleMoment(double)>& moment,
                             std::uint32_t frame_index, const SampleBudget& budget) {
    const std::uint32_t samples = budget.samples;
    if (samples <= 1) {
        const SampleMoment m = moment(0.0);
        return renderer.render(m.head, m.time, frame_index);
    }
    if (renderer.graph().taa) throw std::invalid_argument("jittered samples of a frame with temporal anti-aliasing");
    const bool adaptive = budget.noise > 0.0;
    if (adaptive && !renderer.graph().tile_dispatch)
        throw std::invalid_argument("adaptive sampling needs tile dispatch (the pack's shaders and FrameSettings::tile_dispatch)");
    RenderedFrame first;
    SampleAccumulator left, right;
    std::optional<SampledTiles> sampled_left, sampled_right;   // none: every tile
    AovSums sums_left, sums_right;
    const std::vector<glm::dvec2> pattern = sample_pattern(samples);
    const std::vector<glm::dvec2> lens = lens_pattern(samples);
    const std::vector<double> shutter = shutter_pattern(samples);
    const std::uint32_t width = renderer.graph().output_width;
    for (std::uint32_t k = 0; k < samples; ++k) {
        renderer.set_jitter(pattern[k]);
        if (renderer.aperture() > 0.0) renderer.set_lens(lens[k] * (0.5 * renderer.aperture()));
        renderer.set_light_sample(k);
        const SampleMoment m = moment(shutter[k]);
        RenderedFrame r = renderer.render(m.head, m.time, frame_index);
        const SampledTiles* l = sampled_left ? &*sampled_left : nullptr;
        const SampledTiles* rt = sampled_right ? &*sampled_right : nullptr;
        left.add(r.left, l, r.hdr_left.empty() ? nullptr : &r.hdr_left);
        if (!r.right.pixels.empty()) right.add(r.right, rt, r.hdr_right.empty() ? nullptr : &r.hdr_right);
        if (!r.aovs_left.empty()) add_samples(sums_left, r.aovs_left, l, width);
        if (!r.aovs_right.empty()) add_samples(sums_right, r.aovs_right, rt, width);
        if (k == 0) {
            first = std::move(r);
        } else {
            add_stats(first.stats, r.stats);
        }
        SampleProgress progress{k + 1, samples};
        if (adaptive && k + 1 >= std::max(budget.min_samples, 2u)) {
            std::size_t noisy_left = 0, noisy_right = 0;
            sampled_left = left.tiles_above(budget.noise, &noisy_left);
            if (right.samples() > 0) sampled_right = right.tiles_above(budget.noise, &noisy_right);
            const std::size_t tiles = sampled_left->active.size() * (sampled_right ? 2 : 1);
            const std::size_t sampling = sampled_left->count() + (sampled_right ? sampled_right->count() : 0);
            progress.tiles_sampling = static_cast<double>(sampling) / static_cast<double>(tiles);
            progress.noisy_pixels = noisy_left + noisy_right;
            renderer.set_sampled_tiles(&*sampled_left, sampled_right ? &*sampled_right : nullptr);
        }
        const std::size_t pixels = left.counts().size() + right.counts().size();
        progress.mean_samples = static_cast<double>(left.taken() + right.taken()) / static_cast<double>(std::max<std::size_t>(pixels, 1));
        if (budget.progress) budget.progress(progress);
        if (adaptive && progress.tiles_sampling == 0.0) break;
    }
    renderer.set_jitter(glm::dvec2(0.0));
    renderer.set_lens(glm::dvec2(0.0));
    renderer.set_light_sample(std::nullopt);
    renderer.set_sampled_tiles(nullptr, nullptr);
    first.left = left.mean();
    first.hdr_left = left.hdr_mean();
    if (right.samples() > 0) first.right = right.mean(), first.hdr_right = right.hdr_mean();
    if (!sums_left.empty()) mean_samples(first.aovs_left, sums_left, left.counts());
    if (!sums_right.empty()) mean_samples(first.aovs_right, sums_right, right.counts());
    return first;
}

}  // namespace fg
