// What a reader says while it works, for whoever watches it from outside: the library it is about
// to call and what for (so a crash inside it can be named), and the work done (so a deadline can
// grow with progress). The isolated reading (isolated_reading.h) listens; in-process nobody does.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace tstyles {

class ReadingMonitor {
public:
    virtual ~ReadingMonitor() = default;
    // About to call `library` ("NetCDF/HDF5 library", "the NIfTI reader") for `doing` ("reading the
    // variable list") on `file`. Called often with the same values: a listener keeps it cheap.
    virtual void enterStage(const std::filesystem::path& file, std::string_view library, std::string_view doing) = 0;
    // One more time-step read, of `bytes` values.
    virtual void stepRead(std::uint64_t bytes) = 0;
};

// The calls readers make; nothing happens without a monitor (reading in-process).
inline void reportStage(ReadingMonitor* monitor, const std::filesystem::path& file, std::string_view library,
                        std::string_view doing) {
    if (monitor != nullptr) monitor->enterStage(file, library, doing);
}
inline void reportStepRead(ReadingMonitor* monitor, std::uint64_t bytes) {
    if (monitor != nullptr) monitor->stepRead(bytes);
}

}  // namespace tstyles
