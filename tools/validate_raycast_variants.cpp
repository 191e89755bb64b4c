// Build-time tool: flattens shaders/raycast.frag for every raycasting variant a frame can request
// (requestableRaycastVariants) and checks each with glslangValidator, a few at a time, so that a
// mistake in any compositor, walk or switch combination fails the build and not, at best, an image.
// Usage: validate_raycast_variants SHADER_DIR GLSLANG_VALIDATOR WORK_DIR STAMP
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "tstyles/gl/shader_preprocessor.h"
#include "tstyles/render/raycast_variant.h"

extern char** environ;

namespace {

constexpr int kReportedFailures = 3;

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// "ERROR: N:L: ..." with N a source-string number becomes "ERROR: shaders/FILE:L: ...".
std::string nameFiles(const std::string& log, const std::vector<std::string>& files) {
    std::string result = log;
    for (std::size_t index = files.size(); index-- > 0;) {
        for (const char* kind : {"ERROR: ", "WARNING: "}) {
            const std::string from = kind + std::to_string(index) + ":";
            const std::string to = kind + std::string("shaders/") + files[index] + ":";
            for (auto at = result.find(from); at != std::string::npos; at = result.find(from, at + to.size()))
                result.replace(at, from.size(), to);
        }
    }
    return result;
}

struct Job {
    std::size_t index;
    std::filesystem::path shader;
    std::filesystem::path log;
    std::vector<std::string> files;
};

pid_t startValidator(const std::string& validator, const Job& job) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::string shader = job.shader.string();
    std::vector<char*> arguments{const_cast<char*>(validator.c_str()), shader.data(), nullptr};
    pid_t pid = -1;
    const int error = posix_spawnp(&pid, validator.c_str(), &actions, nullptr, arguments.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error("cannot run " + validator);
    return pid;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::cerr << "usage: validate_raycast_variants SHADER_DIR GLSLANG_VALIDATOR WORK_DIR STAMP\n";
        return 2;
    }
    const std::filesystem::path shaderDirectory = argv[1];
    const std::string validator = argv[2];
    const std::filesystem::path work = argv[3];
    const std::filesystem::path stamp = argv[4];
    try {
        std::filesystem::create_directories(work);
        const auto reader = [&](const std::string& name) -> std::optional<std::string> {
            if (!std::filesystem::is_regular_file(shaderDirectory / name)) return std::nullopt;
            return readFile(shaderDirectory / name);
        };
        const auto variants = tstyles::requestableRaycastVariants();
        std::vector<Job> jobs;
        for (std::size_t index = 0; index < variants.size(); ++index) {
            const auto flat = tstyles::flattenShader("raycast.frag", reader, variants[index].defines(),
                                                     variants[index].modules());
            Job job{index, work / ("variant-" + std::to_string(index) + ".frag"),
                    work / ("variant-" + std::to_string(index) + ".log"), flat.files};
            std::ofstream(job.shader, std::ios::binary | std::ios::trunc) << flat.text;
            jobs.push_back(std::move(job));
        }
        const std::size_t parallel = std::max(1u, std::thread::hardware_concurrency());
        std::map<pid_t, const Job*> running;
        std::size_t next = 0;
        int failures = 0;
        while (next < jobs.size() || !running.empty()) {
            while (next < jobs.size() && running.size() < parallel) {
                running.emplace(startValidator(validator, jobs[next]), &jobs[next]);
                ++next;
            }
            int status = 0;
            const pid_t done = waitpid(-1, &status, 0);
            const auto found = running.find(done);
            if (found == running.end()) continue;
            const Job& job = *found->second;
            running.erase(found);
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
                // One mistake usually breaks many variants: the first few say what it is.
                if (++failures > kReportedFailures) continue;
                std::cerr << "glslangValidator rejected the raycasting variant " << variants[job.index].describe()
                          << " (" << job.shader.string() << "):\n"
                          << nameFiles(readFile(job.log), job.files) << "\n";
            }
        }
        if (failures > 0) {
            std::cerr << failures << " of " << jobs.size() << " raycasting variants do not compile\n";
            return 1;
        }
        std::ofstream(stamp, std::ios::trunc) << jobs.size() << " variants validated\n";
        std::cout << "validate_raycast_variants: " << jobs.size() << " raycasting variants compile\n";
    } catch (const std::exception& error) {
        std::cerr << "validate_raycast_variants: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
