// Raw reads with a size check up front; gzip through zlib, with the shortfall counted after inflating.
#include "file_bytes.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// Deflate cannot expand data more than about 1032 times (RFC 1951: a 258-byte match per two
// bits at best), so a stream shorter than that share of `expected` cannot hold it: said before
// any memory is taken for what a damaged header claims.
constexpr std::uint64_t kMaxDeflateRatio = 1032;

std::vector<std::uint8_t> readRaw(const std::filesystem::path& file, std::uint64_t offset, std::size_t expected,
                                  const std::string& what) {
    std::vector<std::uint8_t> bytes(expected);
    std::ifstream in(file, std::ios::binary);
    in.seekg(std::streamoff(offset));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(expected));
    if (!in) throwInputError(file, "", "cannot read " + what);
    return bytes;
}

struct GzipCloser {
    void operator()(gzFile file) const { gzclose(file); }
};

std::vector<std::uint8_t> readGzip(const std::filesystem::path& file, std::uint64_t offset, std::size_t expected,
                                   const std::string& what, TrailingData trailing) {
    const int descriptor = ::open(file.c_str(), O_RDONLY);
    if (descriptor < 0) throwInputError(file, "", "cannot be opened for reading");
    if (::lseek(descriptor, off_t(offset), SEEK_SET) != off_t(offset)) {
        ::close(descriptor);
        throwInputError(file, "", "is truncated: " + what + " should start at byte " + std::to_string(offset));
    }
    // gzdopen owns the descriptor from here on; gzclose closes both.
    std::unique_ptr<gzFile_s, GzipCloser> stream(gzdopen(descriptor, "rb"));
    if (!stream) {
        ::close(descriptor);
        throwInputError(file, "", "cannot start decompressing " + what);
    }
    const auto fail = [&](std::size_t done) {
        int code = 0;
        const char* message = gzerror(stream.get(), &code);
        throwInputError(file, "", what + " is not valid gzip data: " + std::string(message ? message : "?") +
                                      " after " + std::to_string(done) + " of " + std::to_string(expected) +
                                      " bytes");
    };
    // The buffer grows with what the stream yields, so a header that overstates the size costs
    // no more memory than the data that is really there.
    constexpr std::size_t kChunk = std::size_t(64) << 20;
    std::vector<std::uint8_t> bytes;
    std::size_t done = 0;
    while (done < expected) {
        const std::size_t chunk = std::min(expected - done, kChunk);
        bytes.resize(done + chunk);
        const int read = gzread(stream.get(), bytes.data() + done, unsigned(chunk));
        if (read < 0) fail(done);
        done += std::size_t(read);
        if (std::size_t(read) < chunk) break;
    }
    if (done < expected) {
        throwInputError(file, "",
                        "is truncated: " + what + " needs " + std::to_string(expected) +
                            " bytes once decompressed, the gzip stream holds only " + std::to_string(done));
    }
    unsigned char extra = 0;
    if (trailing == TrailingData::Refused && gzread(stream.get(), &extra, 1) > 0)
        throwInputError(file, "",
                        "is too large: the gzip stream holds more than the " + std::to_string(expected) +
                            " bytes of " + what);
    return bytes;
}

}  // namespace

void requireDataInFile(const std::filesystem::path& file, std::uint64_t offset, double expected,
                       DataEncoding encoding, const std::string& what) {
    const std::uint64_t size = regularFileSize(file, what);
    const std::uint64_t available = size > offset ? size - offset : 0;
    const std::string needed = std::to_string(std::uint64_t(std::min(expected, 1.8e19)));
    if (encoding == DataEncoding::Raw && expected > double(available))
        throwInputError(file, "",
                        "is truncated: " + what + ": " + needed + " bytes from byte " + std::to_string(offset) +
                            ", the file has only " + std::to_string(available));
    if (encoding == DataEncoding::Gzip && expected / double(kMaxDeflateRatio) > double(available + 64))
        throwInputError(file, "",
                        "is truncated: " + what + ": " + needed + " bytes once decompressed, more than the " +
                            std::to_string(available) + " compressed bytes can hold (deflate expands at most " +
                            std::to_string(kMaxDeflateRatio) + " times)");
}

std::vector<std::uint8_t> readDataBytes(const std::filesystem::path& file, std::uint64_t offset,
                                        std::size_t expected, DataEncoding encoding, const std::string& what,
                                        TrailingData trailing) {
    requireDataInFile(file, offset, double(expected), encoding, what);
    return encoding == DataEncoding::Raw ? readRaw(file, offset, expected, what)
                                         : readGzip(file, offset, expected, what, trailing);
}

bool isGzipFile(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) return false;
    std::ifstream in(file, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    in.read(reinterpret_cast<char*>(magic), 2);
    return in && magic[0] == 0x1f && magic[1] == 0x8b;
}

}  // namespace tstyles
