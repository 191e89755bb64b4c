// main() for the replay executables (tests/fuzz/CMakeLists.txt): runs the fuzz target's
// LLVMFuzzerTestOneInput once on each file of the folders and files given, as libFuzzer would on
// its corpus, and says how many it ran. A finding aborts, as under libFuzzer.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::uint8_t> fileBytes(const std::filesystem::path& file) {
    std::ifstream stream(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

void replay(const std::filesystem::path& file) {
    std::cout << file.filename().string() << std::endl;  // the last name printed is the culprit
    const std::vector<std::uint8_t> bytes = fileBytes(file);
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t count = 0;
    for (int index = 1; index < argc; ++index) {
        const std::filesystem::path input = argv[index];
        if (!std::filesystem::is_directory(input)) {
            replay(input);
            ++count;
            continue;
        }
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(input))
            if (entry.is_regular_file()) files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        for (const auto& file : files) replay(file);
        count += files.size();
    }
    if (count == 0) {
        std::cerr << "replay: no inputs in the folders given\n";
        return 1;
    }
    std::cout << "replayed " << count << " inputs\n";
    return 0;
}
