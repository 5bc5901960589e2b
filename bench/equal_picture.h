#pragma once
// The headline of the head traces: for each scene, trace and pixel set, the cheapest setting whose
// picture is at least as close to the ground truth as naive sphere tracing at one sample per pixel
// (median picture PSNR over the trace's frames), and its time against naive's. What a user wants
// to know: how much faster the same picture comes, or whether it comes at all.
#include <string>
#include <vector>

#include "sequence_report.h"

namespace fg::bench {

struct EqualPicture {
    std::string scene, trace, pixels;
    const SequenceRow* naive = nullptr;
    const SequenceRow* cheapest = nullptr;   // null: no other setting reaches naive's picture
    const SequenceRow* best = nullptr;       // the setting with the best picture, naive included
};

// One entry per scene, trace and pixel set that has a naive row without error, in row order.
std::vector<EqualPicture> cheapest_at_naive_picture(const std::vector<SequenceRow>& rows);

// The Markdown section, headed "Time at naive's picture".
std::string equal_picture_markdown(const std::vector<EqualPicture>& entries);

}  // namespace fg::bench
