#pragma once
// Progress of long work on stderr (an offline render's frames or samples, an export's blocks):
// done of the total, their rate and the time left, and a note (adaptive sampling's noise). On a
// terminal one line redraws itself; in a batch log (Slurm, kubectl logs) each update is its own
// line, at most one every few seconds.
#include <chrono>
#include <cstdio>
#include <string>

namespace fg {

class ProgressBar {
public:
    ProgressBar(int total, std::FILE* out = stderr, std::string unit = "frames");
    // One more frame finished; skipped frames (already on disk) do not count towards the speed.
    void advance(bool skipped);
    void set_note(std::string note) { note_ = std::move(note); }
    void finish();
    double frames_per_second() const;

private:
    void draw(bool force);

    int total_, done_ = 0, rendered_ = 0, skipped_ = 0;
    std::string unit_, note_;
    std::FILE* out_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace fg
