// Redirection of file descriptor 2 into a temporary file, undone in the destructor.
#include "tstyles/core/stderr_capture.h"

#include <iostream>

#include <unistd.h>

namespace tstyles {
namespace {

// C stdio and the C++ streams each buffer on their own (std::clog fully: OpenImageIO's PNG reader
// writes there), so both are emptied into whichever file descriptor 2 is at the time.
void flushAll() {
    std::fflush(stderr);
    std::clog.flush();
    std::cerr.flush();
}

std::string withoutPrefix(std::string line) {
    for (const char* prefix : {"libpng error: ", "libpng warning: ", "** ERROR: ", "** WARNING: ", "** "})
        if (line.rfind(prefix, 0) == 0) return line.substr(std::string(prefix).size());
    return line;
}

}  // namespace

StderrCapture::StderrCapture() {
    flushAll();
    captured_ = std::tmpfile();
    if (captured_ == nullptr) return;  // nothing to capture into: the library prints as it would
    savedDescriptor_ = ::dup(STDERR_FILENO);
    if (savedDescriptor_ < 0 || ::dup2(::fileno(captured_), STDERR_FILENO) < 0) {
        if (savedDescriptor_ >= 0) ::close(savedDescriptor_);
        savedDescriptor_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    flushAll();
    if (savedDescriptor_ >= 0) {
        ::dup2(savedDescriptor_, STDERR_FILENO);
        ::close(savedDescriptor_);
    }
    if (captured_ != nullptr) std::fclose(captured_);
}

std::string StderrCapture::text() const {
    if (captured_ == nullptr || savedDescriptor_ < 0) return "";
    flushAll();
    std::string all;
    std::rewind(captured_);
    char buffer[4096];
    for (std::size_t read; (read = std::fread(buffer, 1, sizeof buffer, captured_)) > 0;) all.append(buffer, read);
    std::fseek(captured_, 0, SEEK_END);
    std::string joined;
    std::size_t start = 0;
    while (start < all.size()) {
        std::size_t end = all.find('\n', start);
        if (end == std::string::npos) end = all.size();
        const std::string line = withoutPrefix(all.substr(start, end - start));
        if (!line.empty()) joined += (joined.empty() ? "" : "; ") + line;
        start = end + 1;
    }
    return joined;
}

}  // namespace tstyles
