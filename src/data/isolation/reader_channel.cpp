// Records on the reader pipe: a kind byte, a 32-bit length, then the payload (numbers in the
// machine's order, strings with their length first: both ends are the same program).
#include "reader_channel.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <unistd.h>

namespace tstyles {
namespace {

enum RecordKind : std::uint8_t { kStage = 1, kStepRead = 2, kFailure = 3, kResultReady = 4 };

template <typename T>
void appendNumber(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void appendText(std::string& out, std::string_view text) {
    appendNumber(out, std::uint32_t(text.size()));
    out.append(text);
}

// Reads the fields of one payload in order; a short payload is a broken child, not bad input.
class PayloadCursor {
public:
    explicit PayloadCursor(std::string_view payload) : rest_(payload) {}
    template <typename T>
    T number() {
        T value{};
        std::memcpy(&value, take(sizeof value).data(), sizeof value);
        return value;
    }
    std::string text() { return std::string(take(number<std::uint32_t>())); }

private:
    std::string_view take(std::size_t bytes) {
        if (bytes > rest_.size()) throw std::runtime_error("reader channel: a record is shorter than its fields");
        const std::string_view taken = rest_.substr(0, bytes);
        rest_.remove_prefix(bytes);
        return taken;
    }
    std::string_view rest_;
};

}  // namespace

void ReaderChannelWriter::send(std::uint8_t kind, const std::string& payload) {
    std::string record;
    appendNumber(record, kind);
    appendNumber(record, std::uint32_t(payload.size()));
    record += payload;
    std::size_t written = 0;
    while (written < record.size()) {
        const ssize_t count = ::write(fd_, record.data() + written, record.size() - written);
        if (count < 0 && errno == EINTR) continue;
        if (count <= 0) ::_exit(1);  // the parent is gone: nobody wants the series any more
        written += std::size_t(count);
    }
}

void ReaderChannelWriter::enterStage(const std::filesystem::path& file, std::string_view library,
                                     std::string_view doing) {
    if (last_.doing == doing && last_.library == library && last_.file == file) return;
    last_ = {file, std::string(library), std::string(doing)};
    std::string payload;
    appendText(payload, file.string());
    appendText(payload, library);
    appendText(payload, doing);
    send(kStage, payload);
}

void ReaderChannelWriter::stepRead(std::uint64_t bytes) {
    std::string payload;
    appendNumber(payload, bytes);
    send(kStepRead, payload);
}

void ReaderChannelWriter::sendFailure(const ReaderFailure& failure) {
    std::string payload;
    appendNumber(payload, std::uint8_t(failure.kind));
    appendText(payload, failure.message);
    appendText(payload, failure.path.string());
    appendNumber(payload, std::int32_t(failure.errorCode));
    send(kFailure, payload);
}

void ReaderChannelWriter::sendResultReady(std::uint64_t bytes) {
    std::string payload;
    appendNumber(payload, bytes);
    send(kResultReady, payload);
}

bool ReaderChannelReader::read(ReaderReport& report) {
    char buffer[4096];
    for (;;) {
        const ssize_t count = ::read(fd_, buffer, sizeof buffer);
        if (count < 0 && errno == EINTR) continue;
        if (count < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
        if (count <= 0) return false;
        pending_.insert(pending_.end(), buffer, buffer + count);
        parse(report);
    }
}

void ReaderChannelReader::parse(ReaderReport& report) {
    constexpr std::size_t kHeader = 1 + sizeof(std::uint32_t);
    std::size_t offset = 0;
    while (pending_.size() - offset >= kHeader) {
        std::uint32_t length = 0;
        std::memcpy(&length, pending_.data() + offset + 1, sizeof length);
        if (pending_.size() - offset - kHeader < length) break;
        const auto kind = std::uint8_t(pending_[offset]);
        PayloadCursor payload(std::string_view(pending_.data() + offset + kHeader, length));
        if (kind == kStage) {
            ReaderStage stage;
            stage.file = payload.text();
            stage.library = payload.text();
            stage.doing = payload.text();
            report.stage = std::move(stage);
        } else if (kind == kStepRead) {
            report.stepsRead += 1;
            report.bytesRead += payload.number<std::uint64_t>();
        } else if (kind == kFailure) {
            ReaderFailure failure;
            failure.kind = ReaderFailureKind(payload.number<std::uint8_t>());
            failure.message = payload.text();
            failure.path = payload.text();
            failure.errorCode = payload.number<std::int32_t>();
            report.failure = std::move(failure);
        } else if (kind == kResultReady) {
            report.resultBytes = payload.number<std::uint64_t>();
        } else {
            throw std::runtime_error("reader channel: unknown record kind " + std::to_string(kind));
        }
        offset += kHeader + length;
    }
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(offset));
}

}  // namespace tstyles
