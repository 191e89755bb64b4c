// The memory cap and the regular-file check shared by every reader.
#include "tstyles/core/input_limits.h"

#include <iomanip>
#include <sstream>
#include <system_error>

#include <unistd.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {

std::uint64_t defaultMemoryCap() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    // Unknown (a sandbox without /proc): 4 GiB, what a small laptop can still give.
    if (pages <= 0 || pageSize <= 0) return std::uint64_t(4) << 30;
    return std::uint64_t(pages) * std::uint64_t(pageSize) / 2;
}

std::uint64_t memoryCap(const std::optional<std::uint64_t>& given) { return given ? *given : defaultMemoryCap(); }

std::string byteCountText(double bytes) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1);
    if (bytes < 10240.0) text << std::setprecision(0) << bytes << " bytes";
    else if (bytes < 1024.0 * 1024.0) text << bytes / 1024.0 << " KiB";
    else if (bytes < 1024.0 * 1024.0 * 1024.0) text << bytes / (1024.0 * 1024.0) << " MiB";
    else text << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
    return text.str();
}

void requireMemory(const std::filesystem::path& file, const std::string& field, double bytes, std::uint64_t cap,
                   const std::string& what) {
    if (bytes <= double(cap)) return;
    throwInputError(file, field,
                    what + " need " + byteCountText(bytes) + ", more than the " + byteCountText(double(cap)) +
                        " of memory allowed (--max-memory; default half of this machine's memory)");
}

void requireRegularFile(const std::filesystem::path& file, const std::string& what) {
    userPathKind({}, file);  // a name too long, a loop of links, no permission: said as such, not "no such file"
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(file, error);
    if (!std::filesystem::exists(status)) throwInputError(file, "", "no such file (" + what + ")");
    if (std::filesystem::is_directory(status)) throwInputError(file, "", "is a folder, not a " + what);
    if (!std::filesystem::is_regular_file(status))
        throwInputError(file, "", "is not a regular file (a device, FIFO or socket cannot be read as a " + what + ")");
}

std::uint64_t regularFileSize(const std::filesystem::path& file, const std::string& what) {
    requireRegularFile(file, what);
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) throwInputError(file, "", "cannot be read: " + error.message());
    return std::uint64_t(size);
}

}  // namespace tstyles
