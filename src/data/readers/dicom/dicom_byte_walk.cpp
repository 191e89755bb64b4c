// The element headers of Part 10 files: the meta group in explicit VR little endian, then the data
// set in its transfer syntax; sequences and encapsulated pixel data of undefined length are walked
// item by item to their delimiters. Values are skipped, never read.
#include "dicom_byte_walk.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "../../value_decoding.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;
constexpr int kMaxNesting = 32;

class ByteWalk {
public:
    explicit ByteWalk(const std::filesystem::path& file)
        : file_(file), in_(file, std::ios::binary), size_(regularFileSize(file, "DICOM file")) {}

    void walkFile() {
        if (size_ < 132 + 8) damaged(size_, "is shorter than a DICOM preamble and its first element");
        std::uint64_t at = walkMeta(132);
        if (syntax_ == "1.2.840.10008.1.2.1.99") return;  // deflated: GDCM inflates and checks
        implicit_ = syntax_ == "1.2.840.10008.1.2";
        bigEndian_ = syntax_ == "1.2.840.10008.1.2.2";
        walkElements(at, size_, false, 0);
    }

private:
    [[noreturn]] void damaged(std::uint64_t at, const std::string& problem) const {
        throwInputError(file_, "", "is truncated or damaged at byte " + std::to_string(at) + " of " +
                                       std::to_string(size_) + ": " + problem);
    }

    void read(std::uint64_t at, unsigned char* out, std::size_t count) {
        if (at + count > size_) damaged(at, "an element header runs past the end of the file");
        in_.seekg(std::streamoff(at));
        in_.read(reinterpret_cast<char*>(out), std::streamsize(count));
        if (!in_) damaged(at, "cannot be read");
    }

    std::uint32_t number(const unsigned char* bytes, int count, bool bigEndian) const {
        return std::uint32_t(decodeUnsigned(bytes, std::size_t(count), bigEndian ? ByteOrder::Big : ByteOrder::Little));
    }

    static bool hasLongLength(const std::string& vr) {
        for (const char* name : {"OB", "OD", "OF", "OL", "OV", "OW", "SQ", "SV", "UC", "UN", "UR", "UT", "UV"})
            if (vr == name) return true;
        return false;
    }

    // The meta group, always explicit VR little endian; remembers the transfer syntax.
    std::uint64_t walkMeta(std::uint64_t at) {
        unsigned char header[12];
        while (at + 8 <= size_) {
            read(at, header, 8);
            if (number(header, 2, false) != 0x0002) return at;
            const std::string vr(reinterpret_cast<const char*>(header) + 4, 2);
            std::uint64_t length = number(header + 6, 2, false), start = at + 8;
            if (hasLongLength(vr)) {
                read(at + 8, header + 8, 4);
                length = number(header + 8, 4, false);
                start = at + 12;
            }
            if (start + length > size_) damaged(at, "a file meta element claims more bytes than the file has");
            if (number(header + 2, 2, false) == 0x0010 && length < 128) {
                std::string uid(length, '\0');
                read(start, reinterpret_cast<unsigned char*>(uid.data()), length);
                while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) uid.pop_back();
                syntax_ = uid;
            }
            at = start + length;
        }
        if (at != size_) damaged(at, "the file ends inside an element header");
        return at;
    }

    // Elements from `at` to `end`, or to an item delimiter when `untilDelimiter`.
    std::uint64_t walkElements(std::uint64_t at, std::uint64_t end, bool untilDelimiter, int depth) {
        if (depth > kMaxNesting) damaged(at, "sequences nest deeper than " + std::to_string(kMaxNesting));
        unsigned char header[12];
        while (at < end) {
            read(at, header, 8);
            const std::uint32_t group = number(header, 2, bigEndian_), element = number(header + 2, 2, bigEndian_);
            if (group == 0xfffe) {  // item delimiter: always 8 bytes, little or big as the data set
                if (element == 0xe00d && untilDelimiter) return at + 8;
                damaged(at, "an item tag where an element was expected");
            }
            std::uint64_t start = at + 8;
            std::uint32_t length;
            if (implicit_) {
                length = number(header + 4, 4, bigEndian_);
            } else if (hasLongLength(std::string(reinterpret_cast<const char*>(header) + 4, 2))) {
                read(at + 8, header + 8, 4);
                length = number(header + 8, 4, bigEndian_);
                start = at + 12;
            } else {
                length = number(header + 6, 2, bigEndian_);
            }
            const bool pixels = group == 0x7fe0 && element == 0x0010 && depth == 0;
            if (pixels && length != kUndefinedLength) return start;  // its length is checked with the pixels
            if (length == kUndefinedLength) {
                at = walkItems(start, end, depth + 1);
            } else {
                if (start + length > end) damaged(at, "an element claims more bytes than the file has");
                at = start + length;
            }
            if (pixels) return at;  // what follows the pixels is not read
        }
        if (untilDelimiter) damaged(at, "a sequence item has no end");
        return at;
    }

    // Items of a sequence (or fragments of encapsulated pixels) up to the sequence delimiter.
    std::uint64_t walkItems(std::uint64_t at, std::uint64_t end, int depth) {
        unsigned char header[8];
        while (at < end) {
            read(at, header, 8);
            const std::uint32_t group = number(header, 2, bigEndian_), element = number(header + 2, 2, bigEndian_);
            const std::uint32_t length = number(header + 4, 4, bigEndian_);
            if (group != 0xfffe) damaged(at, "a sequence holds something that is not an item");
            if (element == 0xe0dd) return at + 8;
            if (element != 0xe000) damaged(at, "a sequence holds an unknown delimiter");
            if (length == kUndefinedLength) {
                at = walkElements(at + 8, end, true, depth + 1);
            } else {
                if (at + 8 + length > end) damaged(at, "a sequence item claims more bytes than the file has");
                at += 8 + std::uint64_t(length);
            }
        }
        damaged(at, "a sequence has no end");
    }

    std::filesystem::path file_;
    std::ifstream in_;
    std::uint64_t size_ = 0;
    std::string syntax_ = "1.2.840.10008.1.2.1";
    bool implicit_ = false;
    bool bigEndian_ = false;
};

}  // namespace

void requireWholeDicomFile(const std::filesystem::path& file) { ByteWalk(file).walkFile(); }

}  // namespace tstyles
