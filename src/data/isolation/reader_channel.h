// The pipe between an isolated reader process and its parent: the child says which stage it
// enters and what it has read (a ReadingMonitor), then how it ended (an error, or a result waiting
// in shared memory); the parent collects those records as they come, without blocking.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/data/reading_monitor.h"

namespace tstyles {

// How a read that threw ended, so the parent can throw the same.
enum class ReaderFailureKind : std::uint8_t { Input = 1, OutOfMemory = 2, Filesystem = 3, Other = 4 };

struct ReaderFailure {
    ReaderFailureKind kind = ReaderFailureKind::Other;
    std::string message;         // what(): for InputError the whole "file: field: problem"
    std::filesystem::path path;  // filesystem_error's first path
    int errorCode = 0;           // filesystem_error's code (generic category)
};

// The library and stage the child entered last, on which file.
struct ReaderStage {
    std::filesystem::path file;
    std::string library;
    std::string doing;
};

// Everything the parent knows of the child so far.
struct ReaderReport {
    std::optional<ReaderStage> stage;
    std::uint64_t stepsRead = 0;
    std::uint64_t bytesRead = 0;
    std::optional<ReaderFailure> failure;
    std::optional<std::uint64_t> resultBytes;  // set when the result (a series) is in shared memory
};

// The child's end: a monitor whose every call is one small record on the pipe (a stage only when
// it changed). A parent that has gone away ends the child.
class ReaderChannelWriter : public ReadingMonitor {
public:
    explicit ReaderChannelWriter(int fd) : fd_(fd) {}
    void enterStage(const std::filesystem::path& file, std::string_view library, std::string_view doing) override;
    void stepRead(std::uint64_t bytes) override;
    void sendFailure(const ReaderFailure& failure);
    void sendResultReady(std::uint64_t bytes);

private:
    void send(std::uint8_t kind, const std::string& payload);

    int fd_;
    ReaderStage last_;
};

// The parent's end: read() takes what the pipe holds now into the report; false once the child
// closed its end (it ended, one way or another).
class ReaderChannelReader {
public:
    explicit ReaderChannelReader(int fd) : fd_(fd) {}
    bool read(ReaderReport& report);

private:
    void parse(ReaderReport& report);

    int fd_;
    std::vector<char> pending_;
};

}  // namespace tstyles
