// The scratch folder and the report of an escaped exception (fuzz_support.h).
#include "fuzz_support.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <unistd.h>

// The sanitizers' runtime prints this line to their report file descriptor, which is where
// libFuzzer's own output goes under -close_fd_mask=2 (tools/fuzz.sh) while descriptor 2 is
// closed or captured by StderrCapture. Weak: the replay executables of the normal build have no
// sanitizer runtime.
extern "C" void __sanitizer_report_error_summary(const char* summary) __attribute__((weak));

namespace tstyles_fuzz {
namespace {

// Made with mkdtemp, removed by the destructor of the static that holds it (at exit; libFuzzer
// exits through exit() after -max_total_time and after a finding).
class OwnFolder {
public:
    OwnFolder() {
        const std::filesystem::path base = std::filesystem::temp_directory_path();
        std::string pattern = (base / "tstyles-fuzz-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a scratch folder in " + base.string());
        path_ = pattern;
    }
    ~OwnFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    OwnFolder(const OwnFolder&) = delete;
    OwnFolder& operator=(const OwnFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace

const std::filesystem::path& scratchFolder() {
    static const OwnFolder folder;
    return folder.path();
}

std::filesystem::path writeScratchFile(const std::string& name, std::string_view bytes) {
    const std::filesystem::path file = scratchFolder() / name;
    std::ofstream stream(file, std::ios::binary | std::ios::trunc);
    stream.write(bytes.data(), std::streamsize(bytes.size()));
    if (!stream.flush()) throw std::runtime_error("cannot write the fuzz input " + file.string());
    return file;
}

void reportEscapedException(const char* what) {
    const std::string line = std::string("FUZZ FINDING: an exception other than InputError escaped the parser: ") + what;
    std::fprintf(stderr, "%s\n", line.c_str());
    if (__sanitizer_report_error_summary != nullptr) __sanitizer_report_error_summary(line.c_str());
    std::abort();
}

}  // namespace tstyles_fuzz
