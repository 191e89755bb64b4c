// Raw reads with a size check up front; gzip through zlib, with the shortfall counted after inflating.
#include "file_bytes.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::vector<std::uint8_t> readRaw(const std::filesystem::path& file, std::uint64_t offset, std::size_t expected,
                                  const std::string& what) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) throwInputError(file, "", "cannot be read: " + error.message());
    if (size < offset + expected) {
        throwInputError(file, "",
                        "is truncated: " + what + " needs " + std::to_string(expected) + " bytes from byte " +
                            std::to_string(offset) + ", the file has only " +
                            std::to_string(size > offset ? size - offset : 0));
    }
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
                                   const std::string& what) {
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
    std::vector<std::uint8_t> bytes(expected);
    std::size_t done = 0;
    while (done < expected) {
        const unsigned chunk = unsigned(std::min<std::size_t>(expected - done, 1u << 30));
        const int read = gzread(stream.get(), bytes.data() + done, chunk);
        if (read < 0) {
            int code = 0;
            const char* message = gzerror(stream.get(), &code);
            throwInputError(file, "", what + " is not valid gzip data: " + std::string(message ? message : "?") +
                                          " after " + std::to_string(done) + " of " + std::to_string(expected) +
                                          " bytes");
        }
        if (read == 0) break;
        done += std::size_t(read);
    }
    if (done < expected) {
        throwInputError(file, "",
                        "is truncated: " + what + " needs " + std::to_string(expected) +
                            " bytes once decompressed, the gzip stream holds only " + std::to_string(done));
    }
    return bytes;
}

}  // namespace

std::vector<std::uint8_t> readDataBytes(const std::filesystem::path& file, std::uint64_t offset,
                                        std::size_t expected, DataEncoding encoding, const std::string& what) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throwInputError(file, "", "not found (" + what + ")");
    return encoding == DataEncoding::Raw ? readRaw(file, offset, expected, what)
                                         : readGzip(file, offset, expected, what);
}

bool isGzipFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    in.read(reinterpret_cast<char*>(magic), 2);
    return in && magic[0] == 0x1f && magic[1] == 0x8b;
}

}  // namespace tstyles
