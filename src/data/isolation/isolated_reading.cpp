// The reader process: fork, read in the child, watch it from the parent (isolated_reading.h). The
// child only runs our reading code and the libraries beneath it, then _exits: it never returns
// into the caller's code, flushes no stdio buffer of the parent's, touches no OpenGL.
#include "tstyles/data/isolated_reading.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "reader_channel.h"
#include "../series_transfer.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

#if defined(__SANITIZE_ADDRESS__)
#define TSTYLES_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TSTYLES_ADDRESS_SANITIZER 1
#endif
#endif

namespace tstyles {
namespace {

[[noreturn]] void failSystem(const std::filesystem::path& file, const char* doing) {
    throw std::runtime_error(file.string() + ": cannot " + doing + " for the reader process: " + std::strerror(errno));
}

class OwnedFd {
public:
    explicit OwnedFd(int fd) : fd_(fd) {}
    ~OwnedFd() { reset(); }
    OwnedFd(const OwnedFd&) = delete;
    OwnedFd& operator=(const OwnedFd&) = delete;
    int get() const { return fd_; }
    void reset() {
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }
    void release() { fd_ = -1; }

private:
    int fd_;
};

// The child until it is reaped: ended and reaped on every way out of the parent's watch, so no
// zombie and no orphaned reader is left behind.
class ReaderProcess {
public:
    explicit ReaderProcess(pid_t pid) : pid_(pid) {}
    ~ReaderProcess() {
        if (!reaped_) {
            ::kill(pid_, SIGKILL);
            reap();
        }
    }
    ReaderProcess(const ReaderProcess&) = delete;
    ReaderProcess& operator=(const ReaderProcess&) = delete;
    void kill() { ::kill(pid_, SIGKILL); }
    // The wait status; -1 where it cannot be had (SIGCHLD ignored by the embedding program).
    int reap() {
        int status = 0;
        pid_t done = 0;
        do done = ::waitpid(pid_, &status, 0);
        while (done < 0 && errno == EINTR);
        reaped_ = true;
        return done == pid_ ? status : -1;
    }

private:
    pid_t pid_;
    bool reaped_ = false;
};

#ifndef TSTYLES_ADDRESS_SANITIZER
// Bytes of data segment (VmData) the process holds now: what the child inherited. (Under
// AddressSanitizer the child takes no data limit: its shadow memory would exceed any.)
std::uint64_t dataSegmentBytes() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmData:") {
            std::uint64_t kibibytes = 0;
            status >> kibibytes;
            return kibibytes * 1024;
        }
        status.ignore(4096, '\n');
    }
    return 0;
}
#endif

// The child's process settings: it dies with its parent, leaves no core file, keeps the user's
// terminal clean (what the libraries print, an assertion inside one, goes nowhere: the parent says
// what went wrong), leaves Ctrl-C to the parent, and allocates within its limit.
void prepareReaderChild(const IsolationLimits& limits, pid_t parent) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);
    const rlimit noCore{0, 0};
    ::setrlimit(RLIMIT_CORE, &noCore);
#ifndef TSTYLES_ADDRESS_SANITIZER
    if (const int nowhere = ::open("/dev/null", O_WRONLY | O_CLOEXEC); nowhere >= 0) {
        ::dup2(nowhere, STDOUT_FILENO);
        ::dup2(nowhere, STDERR_FILENO);
        ::close(nowhere);
    }
#else
    ::dup2(STDERR_FILENO, STDOUT_FILENO);  // a sanitizer's report in the child still reaches the log
#endif
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGPIPE, SIG_IGN);
#ifndef TSTYLES_ADDRESS_SANITIZER
    // Faults end the child plainly (no crash handler of an embedding program runs in it).
    for (int fault : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(fault, SIG_DFL);
    if (limits.memoryBytes) {
        const rlim_t cap = rlim_t(dataSegmentBytes() + *limits.memoryBytes);
        const rlimit data{cap, cap};
        ::setrlimit(RLIMIT_DATA, &data);
    }
#else
    (void)limits;
#endif
}

[[noreturn]] void runReaderChild(int channelFd, int resultFd, const IsolatedWork& work, const IsolationLimits& limits,
                                 pid_t parent) {
    prepareReaderChild(limits, parent);
    ReaderChannelWriter channel(channelFd);
    try {
        channel.sendResultReady(work(channel, resultFd));
    } catch (const InputError& error) {
        channel.sendFailure({ReaderFailureKind::Input, error.what(), {}, 0});
    } catch (const std::bad_alloc&) {
        channel.sendFailure({ReaderFailureKind::OutOfMemory, "", {}, 0});
    } catch (const std::filesystem::filesystem_error& error) {
        channel.sendFailure({ReaderFailureKind::Filesystem, error.what(), error.path1(), error.code().value()});
    } catch (const std::exception& error) {
        channel.sendFailure({ReaderFailureKind::Other, error.what(), {}, 0});
    } catch (...) {
        channel.sendFailure({ReaderFailureKind::Other, "an unknown exception", {}, 0});
    }
    ::_exit(0);
}

// "the NetCDF/HDF5 library" and "reading the variable list", or the plainest words when the
// reader said nothing before it went.
std::filesystem::path stageFile(const ReaderReport& report, const std::filesystem::path& file) {
    return report.stage && !report.stage->file.empty() ? report.stage->file : file;
}
std::string stageLibrary(const ReaderReport& report) {
    return report.stage ? report.stage->library : std::string("the reader");
}
std::string stageDoing(const ReaderReport& report) {
    return report.stage ? report.stage->doing : std::string("reading it");
}

[[noreturn]] void throwFailure(const std::filesystem::path& file, const ReaderReport& report,
                               const IsolationLimits& limits) {
    const ReaderFailure& failure = *report.failure;
    switch (failure.kind) {
        case ReaderFailureKind::Input:
            throw InputError(failure.message);
        case ReaderFailureKind::OutOfMemory: {
            const std::string limit =
                limits.memoryBytes ? " (a reader may take " + byteCountText(double(*limits.memoryBytes)) + ")" : "";
            throwInputError(stageFile(report, file), "",
                            stageLibrary(report) + " ran out of memory while " + stageDoing(report) + limit +
                                ": the sizes it declares are too large for this machine, or the file is damaged; "
                                "--max-memory or --steps can ask for less");
        }
        case ReaderFailureKind::Filesystem:
            throw std::filesystem::filesystem_error(failure.message, failure.path,
                                                    std::error_code(failure.errorCode, std::system_category()));
        case ReaderFailureKind::Other:
            break;
    }
    throw std::runtime_error(failure.message);
}

// Collects the child's reports until it closes the pipe; ends it when it is silent too long.
void watchReader(ReaderProcess& child, int channelFd, const std::filesystem::path& file, ReaderReport& report,
                 const IsolationLimits& limits) {
    ReaderChannelReader channel(channelFd);
    auto lastSign = std::chrono::steady_clock::now();
    for (;;) {
        const auto silent = std::chrono::steady_clock::now() - lastSign;
        if (silent >= limits.silence) {
            child.kill();
            child.reap();
            throwInputError(stageFile(report, file), "",
                            stageLibrary(report) + " stopped responding while " + stageDoing(report) +
                                " (no progress in " + std::to_string(limits.silence.count() / 1000) +
                                " s; the reader was ended): the file is damaged, or reading it is slower than the deadline allows");
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(limits.silence - silent);
        pollfd watched{channelFd, POLLIN, 0};
        const int ready = ::poll(&watched, 1, int(std::max<std::int64_t>(1, left.count())));
        if (ready < 0 && errno != EINTR) failSystem(file, "watch the pipe");
        if (ready <= 0) continue;
        const std::uint64_t before = report.stepsRead;
        const auto stageBefore = report.stage ? report.stage->doing : std::string();
        if (!channel.read(report)) return;
        if (report.stepsRead != before || (report.stage && report.stage->doing != stageBefore) || report.failure ||
            report.resultBytes)
            lastSign = std::chrono::steady_clock::now();
    }
}

}  // namespace

IsolatedResult::~IsolatedResult() {
    if (fd_ >= 0) ::close(fd_);
}

IsolatedResult runIsolated(const std::filesystem::path& file, const IsolatedWork& work, const IsolationLimits& limits) {
    OwnedFd resultFd(::memfd_create("tstyles-reader-result", MFD_CLOEXEC));
    if (resultFd.get() < 0) failSystem(file, "make shared memory");
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0) failSystem(file, "make a pipe");
    OwnedFd channelFd(pipeFds[0]);
    OwnedFd childEnd(pipeFds[1]);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) failSystem(file, "fork");
    if (pid == 0) runReaderChild(childEnd.get(), resultFd.get(), work, limits, parent);
    ReaderProcess child(pid);
    childEnd.reset();
    ::fcntl(channelFd.get(), F_SETFL, ::fcntl(channelFd.get(), F_GETFL) | O_NONBLOCK);

    ReaderReport report;
    watchReader(child, channelFd.get(), file, report, limits);
    child.reap();
    if (report.failure) throwFailure(file, report, limits);
    if (!report.resultBytes)
        throwInputError(stageFile(report, file), "",
                        stageLibrary(report) + " crashed while " + stageDoing(report) + ": the file is damaged");
    const int fd = resultFd.get();
    resultFd.release();
    return IsolatedResult(fd, *report.resultBytes);
}

Series readIsolated(const std::filesystem::path& file, const IsolatedRead& read, const IsolationLimits& limits) {
    const IsolatedResult result = runIsolated(
        file,
        [&](ReadingMonitor& monitor, int resultFd) {
            Series series = read(monitor);
            monitor.enterStage(file, "the reader", "handing the series over");
            return writeSeries(resultFd, std::move(series));
        },
        limits);
    return readSeries(result.fd(), result.bytes());
}

}  // namespace tstyles
