// Reading a legacy VTK file's keyword lines, ASCII numbers and big-endian binary values, through a
// small buffer from any offset; vtk_legacy_file.cpp builds the parser on these.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tstyles/core/errors.h"
#include "vtk_data_array.h"  // VtkValueType, VtkValueKind

namespace tstyles {

// The file through a buffer: bytes, lines and words from any offset.
class FileCursor {
public:
    explicit FileCursor(const std::filesystem::path& path);
    const std::filesystem::path& path() const { return path_; }
    std::uint64_t offset() const { return bufferStart_ + position_; }
    std::uint64_t size() const { return size_; }
    int peek() { return position_ < filled_ || fill() ? static_cast<unsigned char>(buffer_[position_]) : -1; }
    int get() {
        const int c = peek();
        if (c >= 0) ++position_;
        return c;
    }
    void seek(std::uint64_t offset);
    // Up to `count` bytes; fewer only where the file ends.
    std::size_t read(char* into, std::size_t count);

private:
    bool fill();

    std::filesystem::path path_;
    std::uint64_t size_ = 0;
    std::ifstream stream_;
    std::vector<char> buffer_;
    std::uint64_t bufferStart_ = 0;
    std::size_t position_ = 0;
    std::size_t filled_ = 0;
};

// The rest of the line, its newline consumed and a '\r' dropped; nullopt at the end of the file.
std::optional<std::string> restOfLine(FileCursor& cursor);

// Moves the cursor past any whitespace.
void skipSpace(FileCursor& cursor);

// The line's words, split at spaces and tabs.
std::vector<std::string> wordsOf(const std::string& line);

// The next line that is not blank, as words; nullopt at the end of the file.
std::optional<std::vector<std::string>> nextKeywordLine(FileCursor& cursor);

// Whether the next word is `lowercase` (in any case); the cursor stays where it was.
bool nextWordIs(FileCursor& cursor, std::string_view lowercase);

// The next whitespace-separated word, at most 80 characters kept (a longer one is no number).
bool nextToken(FileCursor& cursor, std::string& token);

// Text from the file as a message may show it: control bytes (binary data read as a keyword) as '?'.
std::string printable(std::string text);

// The number `text` spells whole (a leading '+' allowed), or nullopt.
std::optional<double> numberIn(std::string_view text);

// "my%20var" -> "my var": VTK escapes the characters a name may not hold as %XX.
std::string unescapedName(const std::string& written);

// The value type a legacy type word names ("float", "unsigned_char", any case), or nullopt.
std::optional<VtkValueType> legacyValueType(const std::string& written);

// InputError naming `field` unless `bytes` bytes remain in the file from the cursor.
void requireBytes(const FileCursor& cursor, const std::string& field, std::uint64_t bytes);

// `count` values from the cursor, each handed to `sink` as a double; `field` names them in messages.
template <class Sink>
void readValues(FileCursor& cursor, bool binary, const VtkValueType& type, std::uint64_t count,
                const std::string& field, Sink&& sink) {
    if (binary) {
        requireBytes(cursor, field, count * type.bytes);
        constexpr std::uint64_t kChunk = 1 << 14;
        std::vector<char> chunk(std::size_t(std::min(count, kChunk) * type.bytes));
        for (std::uint64_t done = 0; done < count;) {
            const std::size_t values = std::size_t(std::min(count - done, kChunk));
            if (cursor.read(chunk.data(), values * type.bytes) < values * type.bytes)
                throwInputError(cursor.path(), field, "is truncated: the file ends inside its values");
            for (std::size_t index = 0; index < values; ++index)
                sink(decodeVtkValue(reinterpret_cast<const std::uint8_t*>(chunk.data()) + index * type.bytes, type, true));
            done += values;
        }
        return;
    }
    std::string token;
    for (std::uint64_t index = 0; index < count; ++index) {
        if (!nextToken(cursor, token))
            throwInputError(cursor.path(), field,
                            "is truncated: the file ends after " + std::to_string(index) + " of its " +
                                std::to_string(count) + " numbers");
        const auto value = numberIn(token);
        if (!value)
            throwInputError(cursor.path(), field,
                            "'" + printable(token) + "' is not a number (number " + std::to_string(index + 1) + " of " +
                                std::to_string(count) + ")");
        // Rounded to the type, as in a binary file: magnitudes then agree whichever way it was written.
        sink(type.kind == VtkValueKind::Float && type.bytes == 4 ? double(float(*value)) : *value);
    }
}

}  // namespace tstyles
