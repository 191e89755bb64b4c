// Pass timing: timer queries on a GPU, glFinish and the wall clock on a CPU rasterizer.
#include "tstyles/render/pass_clock.h"

#include "tstyles/gl/gl_api.h"

namespace tstyles {

PassClock::PassClock(bool cpuRasterizer) {
    if (!cpuRasterizer) query_.emplace(TimerQuery::create());
}

void PassClock::start() {
    if (query_) {
        query_->begin();
        return;
    }
    glFinish();
    started_ = std::chrono::steady_clock::now();
}

void PassClock::stop() {
    if (query_) {
        query_->end();
        return;
    }
    glFinish();
    stopped_ = std::chrono::steady_clock::now();
}

double PassClock::milliseconds() const {
    if (query_) return query_->milliseconds();
    return std::chrono::duration<double, std::milli>(stopped_ - started_).count();
}

}  // namespace tstyles
