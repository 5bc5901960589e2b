#include "xr/frame_time_log.h"

#include <algorithm>
#include <fstream>

#include <fmt/format.h>

namespace fg::xr {

std::string FrameTimeLog::summary(double budget_ms, std::size_t skip) const {
    if (rows_.size() <= skip) return {};
    std::vector<double> wall;
    for (std::size_t i = skip; i < rows_.size(); ++i) wall.push_back(rows_[i].wall_ms);
    std::sort(wall.begin(), wall.end());
    const auto at = [&](double q) { return wall[std::min(wall.size() - 1, static_cast<std::size_t>(q * static_cast<double>(wall.size())))]; };
    std::string line = fmt::format("frame times (xrBeginFrame to xrEndFrame) after the first {}: median {:.1f} ms, p99 {:.1f} ms, longest {:.1f} ms",
                                   skip, at(0.5), at(0.99), wall.back());
    if (budget_ms > 0.0) {
        const auto over = std::count_if(wall.begin(), wall.end(), [&](double ms) { return ms > 1.5 * budget_ms; });
        line += fmt::format("; {} of {} over 1.5x the {:.4g} ms budget", over, wall.size(), budget_ms);
    }
    return line;
}

bool FrameTimeLog::write_csv(const std::string& path) const {
    std::ofstream out(path);
    out << "frame,wall_ms,period_ms,gpu_ms,level,render_scale\n";
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        const auto& r = rows_[i];
        out << fmt::format("{},{:.3f},{:.3f},{:.3f},{},{:.3f}\n", i, r.wall_ms, r.period_ms, r.gpu_ms, r.level, r.render_scale);
    }
    return static_cast<bool>(out);
}

}  // namespace fg::xr
