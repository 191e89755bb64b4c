// Location of the bundled data folder: the environment, the installed prefix, or the source tree.
#include "tstyles/core/bundled_data.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <system_error>

namespace tstyles {
namespace {

// How far above the binary's folder the prefix may be: PREFIX/bin/tstyles is one up, the Python
// module in PREFIX/lib/python3/dist-packages/tstyles/ (or lib/python3.11/site-packages/tstyles/) four.
constexpr int kMostFoldersUpToThePrefix = 4;

bool isDirectory(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_directory(path, error);
}

}  // namespace

DataDirectoryChoice chooseDataDirectory(const char* environmentValue, const std::filesystem::path& binary,
                                        const std::filesystem::path& sourceTreeData) {
    if (environmentValue != nullptr && *environmentValue != 0)
        return {environmentValue, DataDirectorySource::Environment};
    if (!binary.empty()) {
        std::filesystem::path prefix = binary.parent_path();
        for (int up = 0; up < kMostFoldersUpToThePrefix && prefix.has_relative_path(); ++up) {
            prefix = prefix.parent_path();
            const std::filesystem::path installed = prefix / "share" / "tstyles";
            if (isDirectory(installed)) return {installed, DataDirectorySource::Installed};
        }
    }
    return {sourceTreeData, DataDirectorySource::SourceTree};
}

std::filesystem::path runningBinary() {
    // The link map of the object holding this function: the main program has an empty name (then
    // /proc/self/exe says where it is), a shared module its file.
    Dl_info info{};
    link_map* map = nullptr;
    if (dladdr1(reinterpret_cast<void*>(&runningBinary), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0 &&
        map != nullptr && map->l_name != nullptr && *map->l_name != 0) {
        std::error_code error;
        const std::filesystem::path module = std::filesystem::weakly_canonical(map->l_name, error);
        return error ? std::filesystem::path(map->l_name) : module;
    }
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : executable;
}

DataDirectoryChoice bundledDataChoice() {
    return chooseDataDirectory(std::getenv("TSTYLES_DATA_DIR"), runningBinary(), TSTYLES_BUNDLED_DATA_DIR);
}

std::filesystem::path bundledDataDirectory() { return bundledDataChoice().directory; }

std::string describe(const DataDirectoryChoice& choice) {
    switch (choice.source) {
        case DataDirectorySource::Environment: return choice.directory.string() + " (from TSTYLES_DATA_DIR)";
        case DataDirectorySource::Installed: return choice.directory.string() + " (installed beside the program)";
        case DataDirectorySource::SourceTree: return choice.directory.string() + " (the source tree of this build)";
    }
    return choice.directory.string();
}

}  // namespace tstyles
