// Progress on stderr for `tstyles animate` (and any other long command).
#include "progress_bar.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace tstyles::cli {

std::string formatDuration(double seconds) {
    std::ostringstream text;
    if (seconds < 60.0) {
        text.precision(seconds < 10.0 ? 2 : 3);
        text << seconds << " s";
    } else {
        const int whole = int(std::lround(seconds));
        text << whole / 60 << " min " << (whole % 60 < 10 ? "0" : "") << whole % 60 << " s";
    }
    return text.str();
}

ProgressBar::ProgressBar(std::string what, int total)
    : what_(std::move(what)), total_(std::max(total, 1)), terminal_(isatty(fileno(stderr)) != 0) {}

void ProgressBar::update(int done) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double perItem = done > 0 ? elapsed / done : 0.0;
    const double left = perItem * (total_ - done);
    std::ostringstream line;
    constexpr int kWidth = 30;
    const int filled = kWidth * done / total_;
    line << what_ << " " << done << "/" << total_ << " [" << std::string(std::size_t(filled), '#')
         << std::string(std::size_t(kWidth - filled), ' ') << "]";
    if (done > 0) line << " " << formatDuration(perItem) << " each, " << formatDuration(left) << " left";
    if (terminal_) {
        std::cerr << "\r" << line.str() << "\033[K" << std::flush;
        return;
    }
    const int tenth = 10 * done / total_;
    if (tenth == lastReportedTenth_) return;
    lastReportedTenth_ = tenth;
    std::cerr << line.str() << "\n";
}

void ProgressBar::finish() {
    if (terminal_) std::cerr << "\n";
}

}  // namespace tstyles::cli
