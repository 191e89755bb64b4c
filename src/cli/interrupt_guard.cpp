// The SIGINT flag behind InterruptGuard. A signal handler can only reach static storage, so the
// flag is the one piece of process-wide state here; a lock-free atomic is what a handler may touch.
#include "interrupt_guard.h"

#include <atomic>

namespace tstyles::cli {
namespace {

std::atomic<bool> interruptRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void raiseInterruptFlag(int) { interruptRequested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard() {
    interruptRequested.store(false);
    previous_ = std::signal(SIGINT, raiseInterruptFlag);
}

InterruptGuard::~InterruptGuard() { std::signal(SIGINT, previous_); }

bool InterruptGuard::interrupted() const { return interruptRequested.load(); }

}  // namespace tstyles::cli
