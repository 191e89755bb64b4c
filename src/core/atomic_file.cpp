// Temporary-file-and-rename writes.
#include "tstyles/core/atomic_file.h"

#include <fstream>
#include <system_error>
#include <unistd.h>

#include "tstyles/core/errors.h"

namespace tstyles {

std::filesystem::path temporarySiblingOf(const std::filesystem::path& target) {
    auto name = "." + target.stem().string() + ".tmp" + std::to_string(::getpid()) +
                target.extension().string();
    return target.parent_path() / name;
}

void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& writeTo) {
    const auto temporary = temporarySiblingOf(target);
    try {
        writeTo(temporary);
        std::error_code error;
        std::filesystem::rename(temporary, target, error);
        if (error) throwInputError(target, "", "cannot rename the finished file into place: " + error.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

namespace {
void writeBytes(const std::filesystem::path& target, const char* data, std::size_t size) {
    writeAtomically(target, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throwInputError(target, "", "cannot open for writing");
        out.write(data, static_cast<std::streamsize>(size));
        out.close();
        if (!out) throwInputError(target, "", "write failed (disk full?)");
    });
}
}  // namespace

void writeFileAtomically(const std::filesystem::path& target, std::span<const std::byte> bytes) {
    writeBytes(target, reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

void writeFileAtomically(const std::filesystem::path& target, std::string_view text) {
    writeBytes(target, text.data(), text.size());
}

}  // namespace tstyles
