// A progress line for long work on stderr: done of total, time per item, time left. On a terminal
// the line is redrawn in place; in a log (no terminal) a line is printed at each tenth.
#pragma once

#include <chrono>
#include <string>

namespace tstyles::cli {

class ProgressBar {
public:
    ProgressBar(std::string what, int total);
    // `done` items are finished.
    void update(int done);
    // Ends the line on a terminal.
    void finish();

private:
    std::string what_;
    int total_;
    bool terminal_;
    int lastReportedTenth_ = -1;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// "1.2 s", "3 min 05 s".
std::string formatDuration(double seconds);

}  // namespace tstyles::cli
