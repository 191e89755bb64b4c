// A Series written to a file descriptor and read back exactly (every field, every bit of every
// value): how an isolated reader process hands its series to the parent through shared memory.
#pragma once

#include <cstdint>

#include "tstyles/data/series.h"

namespace tstyles {

// Writes `series` to `fd` from its current offset, freeing each time-step's values and mask once
// written, so the writer never holds two copies. Returns the bytes written. A failed write is a
// std::runtime_error with the system's reason.
std::uint64_t writeSeries(int fd, Series&& series);

// Reads a series written by writeSeries from offset 0 of `fd`, which holds `bytes`. Where `fd`
// can punch holes (a memfd), the pages of each time-step's values are given back as soon as they
// are copied out, so the reader too holds about one copy. A short or inconsistent stream is a
// std::runtime_error.
Series readSeries(int fd, std::uint64_t bytes);

}  // namespace tstyles
