#include "progress_bar.h"

#include <fmt/format.h>
#include <string>
#include <unistd.h>

namespace fg {

namespace {
std::string clock_text(double seconds) {
    long s = static_cast<long>(seconds + 0.5);
    return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}
}  // namespace

ProgressBar::ProgressBar(int total, std::FILE* out, std::string unit)
    : total_(total), unit_(std::move(unit)), out_(out), terminal_(::isatty(::fileno(out)) != 0), start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {
    draw(true);
}

double ProgressBar::frames_per_second() const {
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return seconds > 0.0 ? rendered_ / seconds : 0.0;
}

void ProgressBar::advance(bool skipped) {
    ++done_;
    if (skipped) ++skipped_;
    else ++rendered_;
    draw(false);
}

void ProgressBar::draw(bool force) {
    auto now = std::chrono::steady_clock::now();
    if (!force && !terminal_ && now - last_draw_ < std::chrono::seconds(5)) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    int filled = total_ > 0 ? kWidth * done_ / total_ : kWidth;
    double fps = frames_per_second();
    std::string left = rendered_ > 0 ? clock_text((total_ - done_) / fps) : "?";
    std::string line = fmt::format("[{}{}] {}/{} {}, {:.2f} {}, {} left{}{}", std::string(filled, '#'),
                                   std::string(kWidth - filled, '.'), done_, total_, unit_, fps,
                                   unit_ == "frames" ? "fps" : unit_ + "/s", left,
                                   skipped_ > 0 ? fmt::format(" ({} already done)", skipped_) : "",
                                   note_.empty() ? "" : ", " + note_);
    if (terminal_) fmt::print(out_, "\r{}\x1b[K", line);
    else fmt::print(out_, "{}\n", line);
    std::fflush(out_);
}

void ProgressBar::finish() {
    draw(true);   // the last state, whatever the throttle skipped
    if (terminal_) fmt::print(out_, "\n");
}

}  // namespace fg
