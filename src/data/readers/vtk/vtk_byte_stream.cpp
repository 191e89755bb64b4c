// Base64 as VTK writes it: whitespace anywhere, and padding ('=') that may end a group in the middle
// of an array (VTK encodes a compressed array's header apart from its blocks), so decoding goes on
// after a padded group as if a new base64 text began there.
#include "vtk_byte_stream.h"

#include <algorithm>
#include <cstring>

namespace tstyles {
namespace {

int base64Digit(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

bool VtkByteStream::nextDecodedByte(std::uint8_t& byte) {
    if (pendingNext_ < pendingCount_) {
        byte = pending_[pendingNext_++];
        return true;
    }
    // Four significant characters: digits, then up to two '=' at the end of the group.
    int digits[4] = {0, 0, 0, 0};
    int count = 0;
    int padding = 0;
    while (count < 4 && position_ < text_.size()) {
        const char c = text_[position_++];
        if (isSpace(c)) continue;
        if (c == '=') {
            if (count < 2) return failure_ = "base64 padding '=' in the middle of a group", false;
            ++padding;
            digits[count++] = 0;
            continue;
        }
        const int digit = base64Digit(c);
        if (digit < 0) return failure_ = "a character that is not base64", false;
        if (padding > 0) return failure_ = "base64 digits after padding '=' within a group", false;
        digits[count++] = digit;
    }
    if (count == 0) return false;
    if (count < 4) return failure_ = "base64 text that ends inside a group of four characters", false;
    const std::uint32_t bits = std::uint32_t(digits[0]) << 18 | std::uint32_t(digits[1]) << 12 |
                               std::uint32_t(digits[2]) << 6 | std::uint32_t(digits[3]);
    pending_[0] = std::uint8_t(bits >> 16);
    pending_[1] = std::uint8_t(bits >> 8);
    pending_[2] = std::uint8_t(bits);
    pendingCount_ = 3 - padding;
    pendingNext_ = 0;
    byte = pending_[pendingNext_++];
    return true;
}

bool VtkByteStream::read(std::uint8_t* out, std::size_t count) {
    failure_ = "";
    if (encoding_ == Encoding::Raw) {
        if (text_.size() - position_ < count) return false;
        if (count > 0) std::memcpy(out, text_.data() + position_, count);
        position_ += count;
        return true;
    }
    for (std::size_t index = 0; index < count; ++index)
        if (!nextDecodedByte(out[index])) return false;
    return true;
}

std::uint64_t VtkByteStream::bytesLeftAtMost() const {
    const std::uint64_t left = text_.size() - position_;
    if (encoding_ == Encoding::Raw) return left;
    return std::uint64_t(pendingCount_ - pendingNext_) + left / 4 * 3 + 3;
}

}  // namespace tstyles
