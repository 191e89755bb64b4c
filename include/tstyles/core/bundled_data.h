// Where the bundled data lives (scenes, generated datasets, built-in styles): the one rule that
// picks between the environment, an installed prefix and the source tree (docs/install.md).
#pragma once

#include <filesystem>
#include <string>

namespace tstyles {

enum class DataDirectorySource { Environment, Installed, SourceTree };

struct DataDirectoryChoice {
    std::filesystem::path directory;
    DataDirectorySource source = DataDirectorySource::SourceTree;
};

// The rule, given its inputs: TSTYLES_DATA_DIR when set and not empty; else share/tstyles in the
// prefix that holds `binary` (the executable in PREFIX/bin, or the Python module in
// PREFIX/lib/python3*/.../tstyles), so that a relocated prefix keeps working; else `sourceTreeData`,
// the data/ folder of the source tree the build came from (developers' builds).
DataDirectoryChoice chooseDataDirectory(const char* environmentValue, const std::filesystem::path& binary,
                                        const std::filesystem::path& sourceTreeData);

// The file this code runs from: the executable, or the shared module (Python) it is linked into.
std::filesystem::path runningBinary();

// chooseDataDirectory for this process.
DataDirectoryChoice bundledDataChoice();
std::filesystem::path bundledDataDirectory();

// "/usr/share/tstyles (installed beside the program)", for `tstyles --version`.
std::string describe(const DataDirectoryChoice& choice);

}  // namespace tstyles
