// The peak resident memory of this process (process_memory.h).
#include "tstyles/core/process_memory.h"

#include <sys/resource.h>

namespace tstyles {

std::uint64_t peakResidentBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

}  // namespace tstyles
