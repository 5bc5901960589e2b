#pragma once
// Which frames of a path one run renders: a half-open range A:B of frame numbers, optionally cut
// into N contiguous shards of which this run takes shard I (a job array's task index).
#include <optional>
#include <string>

namespace fg {

struct FrameRange {
    int begin = 0, end = 0;   // [begin, end)
    int size() const { return end > begin ? end - begin : 0; }
};

// "A:B", "A:" (to the end), ":B", or "A" (one frame), clipped to [0, frame_count). Returns
// nothing and sets `error` for text that is none of these or a range outside the path.
std::optional<FrameRange> parse_frame_range(const std::string& text, int frame_count, std::string& error);
// "I/N": shard I (0-based) of N.
bool parse_shard(const std::string& text, int& index, int& count, std::string& error);
// Shard `index` of `count`: contiguous, sizes differ by at most one, together exactly `range`.
FrameRange shard_of(const FrameRange& range, int index, int count);

}  // namespace fg
