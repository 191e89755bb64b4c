// Reading a legacy VTK file's keyword lines, ASCII numbers and big-endian binary values: the buffered
// cursor and the words, numbers, names and types it reads.
#include "vtk_legacy_text.h"

#include <charconv>
#include <cstring>
#include <utility>

#include "tstyles/core/ascii_case.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr std::size_t kMaxLine = 1 << 16;  // keyword lines are short: longer means binary or garbage

bool isLegacySpace(int c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

FileCursor::FileCursor(const std::filesystem::path& path)
    : path_(path), size_(regularFileSize(path, "legacy VTK file")), stream_(path, std::ios::binary),
      buffer_(1 << 18) {
    if (!stream_) throwInputError(path, "", "cannot be opened for reading");
}

void FileCursor::seek(std::uint64_t offset) {
    if (offset >= bufferStart_ && offset <= bufferStart_ + filled_) {
        position_ = std::size_t(offset - bufferStart_);
        return;
    }
    bufferStart_ = offset;
    position_ = filled_ = 0;
}

std::size_t FileCursor::read(char* into, std::size_t count) {
    std::size_t done = 0;
    while (done < count && (position_ < filled_ || fill())) {
        const std::size_t part = std::min(count - done, filled_ - position_);
        std::memcpy(into + done, buffer_.data() + position_, part);
        position_ += part;
        done += part;
    }
    return done;
}

bool FileCursor::fill() {
    bufferStart_ += position_;
    position_ = 0;
    stream_.clear();
    stream_.seekg(std::streamoff(bufferStart_));
    stream_.read(buffer_.data(), std::streamsize(buffer_.size()));
    filled_ = std::size_t(stream_.gcount());
    return filled_ > 0;
}

std::optional<std::string> restOfLine(FileCursor& cursor) {
    if (cursor.peek() < 0) return std::nullopt;
    std::string line;
    for (int c = cursor.get(); c >= 0 && c != '\n'; c = cursor.get()) {
        if (line.size() == kMaxLine)
            throwInputError(cursor.path(), "", "the line at byte " + std::to_string(cursor.offset() - kMaxLine) +
                                                   " is longer than 64 KiB: not a legacy VTK keyword line");
        line += char(c);
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

void skipSpace(FileCursor& cursor) {
    while (isLegacySpace(cursor.peek())) cursor.get();
}

std::vector<std::string> wordsOf(const std::string& line) {
    std::vector<std::string> words;
    std::size_t position = 0;
    while (true) {
        position = line.find_first_not_of(" \t\r\v\f", position);
        if (position == std::string::npos) return words;
        const std::size_t end = std::min(line.find_first_of(" \t\r\v\f", position), line.size());
        words.push_back(line.substr(position, end - position));
        position = end;
    }
}

std::optional<std::vector<std::string>> nextKeywordLine(FileCursor& cursor) {
    skipSpace(cursor);
    const auto line = restOfLine(cursor);
    if (!line) return std::nullopt;
    return wordsOf(*line);
}

bool nextWordIs(FileCursor& cursor, std::string_view lowercase) {
    const std::uint64_t before = cursor.offset();
    skipSpace(cursor);
    std::string word;
    while (word.size() <= lowercase.size() && cursor.peek() >= 0 && !isLegacySpace(cursor.peek())) word += char(cursor.get());
    cursor.seek(before);
    return asciiLowercase(word) == lowercase;
}

bool nextToken(FileCursor& cursor, std::string& token) {
    skipSpace(cursor);
    token.clear();
    while (cursor.peek() >= 0 && !isLegacySpace(cursor.peek())) {
        const char c = char(cursor.get());
        if (token.size() < 80) token += c;
    }
    return !token.empty();
}

std::string printable(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return text;
}

std::optional<double> numberIn(std::string_view text) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);  // from_chars refuses '+'
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::string unescapedName(const std::string& written) {
    std::string name;
    for (std::size_t index = 0; index < written.size(); ++index) {
        unsigned value = 0;
        if (written[index] == '%' && index + 2 < written.size() &&
            std::from_chars(written.data() + index + 1, written.data() + index + 3, value, 16).ptr ==
                written.data() + index + 3) {
            name += char(value);
            index += 2;
        } else {
            name += written[index];
        }
    }
    return name;
}

std::optional<VtkValueType> legacyValueType(const std::string& written) {
    using Kind = VtkValueKind;
    static const std::pair<const char*, VtkValueType> types[] = {
        {"unsigned_char", {"UInt8", Kind::Unsigned, 1}},   {"char", {"Int8", Kind::Signed, 1}},
        {"signed_char", {"Int8", Kind::Signed, 1}},        {"unsigned_short", {"UInt16", Kind::Unsigned, 2}},
        {"short", {"Int16", Kind::Signed, 2}},             {"unsigned_int", {"UInt32", Kind::Unsigned, 4}},
        {"int", {"Int32", Kind::Signed, 4}},               {"unsigned_long", {"UInt64", Kind::Unsigned, 8}},
        {"long", {"Int64", Kind::Signed, 8}},              {"vtktypeint64", {"Int64", Kind::Signed, 8}},
        {"vtktypeuint64", {"UInt64", Kind::Unsigned, 8}},  {"float", {"Float32", Kind::Float, 4}},
        {"double", {"Float64", Kind::Float, 8}},
        // VTK writes vtkIdType arrays as 4-byte ints, whatever its own id size ("long" is 8 bytes: LP64).
        {"vtkidtype", {"Int32", Kind::Signed, 4}}};
    const std::string lowercase = asciiLowercase(written);
    for (const auto& [legacy, type] : types)
        if (lowercase == legacy) return type;
    return std::nullopt;
}

void requireBytes(const FileCursor& cursor, const std::string& field, std::uint64_t bytes) {
    if (bytes > cursor.size() || cursor.offset() > cursor.size() - bytes)
        throwInputError(cursor.path(), field,
                        "is truncated: its values need " + std::to_string(bytes) + " bytes from byte " +
                            std::to_string(cursor.offset()) + ", but the file ends at byte " +
                            std::to_string(cursor.size()));
}

}  // namespace tstyles
