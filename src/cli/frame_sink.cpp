// Movie files and frame folders, written so that nothing half-made is left behind.
#include "frame_sink.h"

#include <cstdio>
#include <system_error>

#include <unistd.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/image/image_io.h"
#include "tstyles/video/video_file.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;

std::string framesText(int count) { return std::to_string(count) + (count == 1 ? " frame" : " frames"); }

bool holdsOnlyFrames(const fs::path& folder) {
    const fs::directory_iterator entries = withUserPath(PathSource{"", "-o"}, folder, [&] { return fs::directory_iterator(folder); });
    for (const fs::directory_entry& entry : entries) {
        const std::string name = entry.path().filename().string();
        if (!entry.is_regular_file() || name.rfind("frame-", 0) != 0 || entry.path().extension() != ".png") return false;
    }
    return true;
}

// Frames go into a hidden sibling folder, which replaces the target when the last one is in.
class FolderSink final : public FrameSink {
public:
    FolderSink(fs::path target, int framesPerSecond)
        : target_(fs::absolute(target).lexically_normal()), framesPerSecond_(framesPerSecond),
          partial_(target_.parent_path() / ("." + target_.filename().string() + ".partial-" + std::to_string(getpid()))) {
        std::error_code error;
        fs::remove_all(partial_, error);
        if (!fs::create_directory(partial_, error))
            throwInputError(target_, "", "cannot make a folder beside it for the frames: " + error.message());
    }
    ~FolderSink() override {
        std::error_code ignored;
        if (!finished_) fs::remove_all(partial_, ignored);
    }
    void add(const Image& frame) override { writeImage(frame, partial_ / frameFileName(count_++)); }
    void finish() override {
        std::error_code error;
        if (fs::exists(target_)) fs::remove_all(target_, error);
        if (error) throwInputError(target_, "", "cannot replace the earlier frames: " + error.message());
        fs::rename(partial_, target_, error);
        if (error) throwInputError(target_, "", "cannot move the frames into place: " + error.message());
        finished_ = true;
    }
    std::string description() const override { return framesText(count_) + " as PNG"; }
    double framesPerSecond() const override { return framesPerSecond_; }

private:
    fs::path target_;
    int framesPerSecond_;
    fs::path partial_;
    int count_ = 0;
    bool finished_ = false;
};

class MovieSink final : public FrameSink {
public:
    MovieSink(const fs::path& target, const MovieSettings& settings)
        : writer_(target, VideoSettings{settings.width, settings.height, settings.framesPerSecond}),
          framesPerSecond_(storedFramesPerSecond(*videoFormatForPath(target), settings.framesPerSecond)) {}
    void add(const Image& frame) override { writer_.addFrame(frame); }
    void finish() override { writer_.finish(); }
    std::string description() const override {
        return framesText(writer_.framesWritten()) + ", " + writer_.codecName();
    }
    double framesPerSecond() const override { return framesPerSecond_; }

private:
    VideoWriter writer_;
    double framesPerSecond_;
};

}  // namespace

std::string frameFileName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", index);
    return name;
}

bool isFrameFolder(const fs::path& output) {
    const std::string text = output.string();
    return (!text.empty() && (text.back() == '/' || text.back() == fs::path::preferred_separator)) ||
           userPathKind(PathSource{"", "-o"}, output) == PathKind::Folder;
}

void requireWritableFrameOutput(const fs::path& output, const MovieSettings& settings) {
    if (!isFrameFolder(output)) {
        requireWritableVideoPath(output, VideoSettings{settings.width, settings.height, settings.framesPerSecond}, "-o");
        return;
    }
    const PathSource source{"", "-o"};
    const fs::path folder = userAbsolutePath(source, output);
    const fs::path target = folder.has_filename() ? folder : folder.parent_path();
    requireOutputFolder(source, target, "frame folder");
    if (userPathKind(source, target) == PathKind::Folder && !holdsOnlyFrames(target))
        throwInputError(output, "-o", "holds files other than frame-NNNN.png; give an empty or new folder");
}

std::unique_ptr<FrameSink> openFrameSink(const fs::path& output, const MovieSettings& settings) {
    if (!isFrameFolder(output)) return std::make_unique<MovieSink>(output, settings);
    const fs::path folder = fs::absolute(output).lexically_normal();
    return std::make_unique<FolderSink>(folder.has_filename() ? folder : folder.parent_path(), settings.framesPerSecond);
}

}  // namespace tstyles::cli
