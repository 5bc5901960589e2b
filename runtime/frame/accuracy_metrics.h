#pragma once
// How far a rendered depth image is from a reference: misclassified hit/miss pixels, depth error
// in units of the pixel's cone radius at the hit, overstepping (a hit beyond the true surface),
// and values that are not finite. Used by the tests and the accuracy benchmark.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "stereo_rig.h"

namespace fg {

struct DepthComparison {
    std::size_t pixels = 0;
    std::size_t both_hit = 0, only_rendered = 0, only_reference = 0;
    std::size_t not_finite = 0;         // NaN or infinite values in the rendered depth
    std::size_t overstepped = 0;        // rendered hit further than the reference by > 1 cone radius
    double misclassified = 0.0;         // (only_rendered + only_reference) / pixels
    double median_error = 0.0, p95_error = 0.0, max_error = 0.0;   // |t - t_ref| / (cone radius at t_ref)
    std::vector<std::size_t> overstepped_pixels;                    // the first few, for messages
};

// `rendered` uses FG_MISS (< 0) for misses, as the depth images do; so does `reference`. With
// `visible` (1 per visible pixel, lens_mask.h), only the pixels a viewer sees are compared.
DepthComparison compare_depths(std::span<const float> rendered, std::span<const double> reference,
                               double pixel_half_diagonal, std::span<const std::uint8_t> visible = {});

}  // namespace fg
