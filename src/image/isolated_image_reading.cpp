// A user's image read in a reader process: OpenImageIO and the format libraries beneath it (libpng,
// libtiff, libjpeg ...) run where a crash or a hang cannot take the program down.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include "tstyles/data/isolated_reading.h"
#include "tstyles/image/image_io.h"

namespace tstyles {
namespace {

void writeAll(int fd, const void* data, std::size_t count) {
    const auto* next = static_cast<const char*>(data);
    while (count > 0) {
        const ssize_t done = ::write(fd, next, count);
        if (done < 0 && errno == EINTR) continue;
        if (done <= 0) throw std::runtime_error(std::string("cannot hand the image over: ") + std::strerror(errno));
        next += done;
        count -= std::size_t(done);
    }
}

void readAll(int fd, void* data, std::size_t count, std::uint64_t offset) {
    auto* next = static_cast<char*>(data);
    while (count > 0) {
        const ssize_t done = ::pread(fd, next, count, off_t(offset));
        if (done < 0 && errno == EINTR) continue;
        if (done <= 0) throw std::runtime_error(std::string("cannot take the image over: ") + std::strerror(errno));
        next += done;
        count -= std::size_t(done);
        offset += std::uint64_t(done);
    }
}

}  // namespace

Image readImageIsolated(const std::filesystem::path& file, std::uint64_t maxBytes) {
    if (readingInProcessRequested()) return readImage(file, maxBytes);
    // The series readers' deadline (30 s of silence, longer under a sanitizer): a viewer on a loaded
    // two-core machine was once silent for over 10 s while reading a bundled style.
    IsolationLimits limits = isolationLimitsFor({file}, ReadOptions{});
    limits.memoryBytes = 2 * maxBytes + (std::uint64_t(1) << 30);
    const IsolatedResult result = runIsolated(
        file,
        [&](ReadingMonitor& monitor, int resultFd) {
            // The parent's OpenImageIO thread pool did not come along into this process: work inline.
            OIIO::attribute("threads", 1);
            monitor.enterStage(file, "the image library (OpenImageIO)", "reading the image");
            const Image image = readImage(file, maxBytes);
            const std::array<int, 2> size{image.width, image.height};
            writeAll(resultFd, size.data(), sizeof size);
            writeAll(resultFd, image.rgba.data(), image.rgba.size() * sizeof(float));
            return std::uint64_t(sizeof size + image.rgba.size() * sizeof(float));
        },
        limits);
    std::array<int, 2> size{};
    if (result.bytes() < sizeof size)
        throw std::runtime_error(file.string() + ": the image reader handed over nothing");
    readAll(result.fd(), size.data(), sizeof size, 0);
    // Checked before the pixels get memory: the size and the bytes handed over must agree.
    const std::uint64_t pixelBytes = std::uint64_t(std::max(size[0], 0)) * std::uint64_t(std::max(size[1], 0)) * 16;
    if (result.bytes() != sizeof size + pixelBytes)
        throw std::runtime_error(file.string() + ": the image reader handed over an inconsistent image");
    Image image(size[0], size[1]);
    readAll(result.fd(), image.rgba.data(), image.rgba.size() * sizeof(float), sizeof size);
    return image;
}

}  // namespace tstyles
