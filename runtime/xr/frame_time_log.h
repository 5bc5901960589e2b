#pragma once
// Each headset frame's wall time (xrBeginFrame to xrEndFrame returning), what the runtime predicted
// and what the governor ran: the figures a hitch shows in, on any runtime. `fgplay xr` prints the
// summary; `--frame-times FILE` writes every row as CSV.
#include <string>
#include <vector>

namespace fg::xr {

struct FrameTimeRow {
    double wall_ms = 0.0;        // xrBeginFrame called to xrEndFrame returned
    double period_ms = 0.0;      // the predicted display period xrWaitFrame gave
    double gpu_ms = 0.0;         // the frame graph's GPU time; 0 where nothing was rendered
    int level = 0;               // the governor's level, and its render scale
    double render_scale = 1.0;
};

class FrameTimeLog {
public:
    void add(const FrameTimeRow& row) { rows_.push_back(row); }
    const std::vector<FrameTimeRow>& rows() const { return rows_; }
    // One line: median, 99th percentile and longest wall time after the first `skip` frames (start-up),
    // and how many exceed 1.5x the budget; empty when there are no such frames.
    std::string summary(double budget_ms, std::size_t skip = 10) const;
    // frame,wall_ms,period_ms,gpu_ms,level,render_scale; false when the file cannot be written.
    bool write_csv(const std::string& path) const;

private:
    std::vector<FrameTimeRow> rows_;
};

}  // namespace fg::xr
