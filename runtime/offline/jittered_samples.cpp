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
    if (samples <= 1) {
        const SampleMoment m = moment(0.0);
        return renderer.render(m.head, m.time, frame_index);
    }
    if (renderer.graph().taa) throw std::invalid_argument("jittered samples of a frame with temporal anti-aliasing");
    RenderedFrame first;
    SampleAccumulator left, right;
    std::vector<float> beauty_left, beauty_right;
    const std::vector<glm::dvec2> pattern = sample_pattern(samples);
    const std::vector<glm::dvec2> lens = lens_pattern(samples);
    const std::vector<double> shutter = shutter_pattern(samples);
    for (std::uint32_t k = 0; k < samples; ++k) {
        renderer.set_jitter(pattern[k]);
        if (renderer.aperture() > 0.0) renderer.set_lens(lens[k] * (0.5 * renderer.aperture()));
        const SampleMoment m = moment(shutter[k]);
        RenderedFrame r = renderer.render(m.head, m.time, frame_index);
        left.add(r.left);
        if (!r.right.pixels.empty()) right.add(r.right);
        if (!r.aovs_left.empty()) add_beauty(beauty_left, r.aovs_left);
        if (!r.aovs_right.empty()) add_beauty(beauty_right, r.aovs_right);
        if (k == 0) {
            first = std::move(r);
        } else {
            add_stats(first.stats, r.stats);
        }
    }
    renderer.set_jitter(glm::dvec2(0.0));
    renderer.set_lens(glm::dvec2(0.0));
    first.left = left.mean();
    if (right.samples() > 0) first.right = right.mean();
    if (!beauty_left.empty()) mean_beauty(first.aovs_left, beauty_left, samples);
    if (!beauty_right.empty()) mean_beauty(first.aovs_right, beauty_right, samples);
    return first;
}

}  // namespace fg
