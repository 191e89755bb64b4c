// Recognising a file by its first bytes (file_magic.h).
#include "file_magic.h"

#include <fstream>

namespace tstyles {

std::string fileStart(const std::filesystem::path& file, std::size_t count) {
    std::ifstream in(file, std::ios::binary);
    std::string start(count, '\0');
    in.read(start.data(), std::streamsize(count));
    start.resize(std::size_t(in.gcount()));
    return start;
}

bool hasMagicAt(std::string_view start, std::size_t offset, std::string_view magic) {
    return start.size() >= offset + magic.size() && start.substr(offset, magic.size()) == magic;
}

}  // namespace tstyles
