// Libraries that print their own complaints to stderr (libpng through OpenImageIO, libnifti,
// HDF5 through libnetcdf) would break our one-line error. While a StderrCapture lives, what is
// written to file descriptor 2 goes to a temporary file instead; text() gives it back, so that a
// message can quote it where it helps.
#pragma once

#include <cstdio>
#include <string>

namespace tstyles {

class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // What was printed so far, on one line (newlines become "; "), without library prefixes such
    // as "libpng error: " or "** ERROR: ".
    std::string text() const;

private:
    std::FILE* captured_ = nullptr;
    int savedDescriptor_ = -1;
};

}  // namespace tstyles
