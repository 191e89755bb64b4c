// The bytes of one VTK XML DataArray as they sit in the file: raw (appended "raw" data) or base64
// text (inline "binary" data, appended "base64" data), read front to back with bounds checked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace tstyles {

class VtkByteStream {
public:
    enum class Encoding { Raw, Base64 };

    VtkByteStream(std::string_view text, Encoding encoding) : text_(text), encoding_(encoding) {}

    // Copies the next `count` bytes to `out`; false when the data ends first or the base64 text is
    // damaged (failure() says which), leaving the stream where it stopped.
    bool read(std::uint8_t* out, std::size_t count);
    // An upper bound of the bytes left, known without decoding: what a size read from the file is
    // checked against before anything is allocated for it.
    std::uint64_t bytesLeftAtMost() const;
    // Why the last read failed: "" (ran out of data) or what was wrong with the base64 text.
    const char* failure() const { return failure_; }

private:
    bool nextDecodedByte(std::uint8_t& byte);

    std::string_view text_;
    Encoding encoding_;
    std::size_t position_ = 0;
    // Base64 decodes four characters into up to three bytes; the ones not yet handed out wait here.
    std::uint8_t pending_[3] = {0, 0, 0};
    int pendingCount_ = 0;
    int pendingNext_ = 0;
    const char* failure_ = "";
};

}  // namespace tstyles
