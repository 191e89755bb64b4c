// Ctrl+C during long work: while an InterruptGuard lives, SIGINT only raises a flag that the work
// polls, so that it can stop between frames and remove what it had begun to write.
#pragma once

#include <csignal>

namespace tstyles::cli {

class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();  // restores the handler that was there before
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;
    bool interrupted() const;

private:
    void (*previous_)(int) = SIG_DFL;
};

}  // namespace tstyles::cli
