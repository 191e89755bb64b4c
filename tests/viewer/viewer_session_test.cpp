// End-to-end tests of `tstyles view`: the real executable in a real window under Xvfb, driven by
// the scripts in tests/viewer/scripts (input events through the viewer's own input path), checked
// against the scenes it saves and against `tstyles render` of those scenes.
//
// Window vs. headless tolerance: both images come from the same shaders on the same device at the
// same size and camera, but the window's frame is assembled from tiles rendered through cropped
// projections (ray origins differ from the one-pass frame in the last bits of a float) and is
// turned into 8 bits by OpenGL when it is copied into the window, while `tstyles render` rounds
// with OpenImageIO. Either may move a channel by one level. We allow at most 2 levels anywhere,
// a mean below 0.05 levels, and at most 0.1 % of pixels off by more than one level; on llvmpipe
// we measured max 1 level and a mean of about 0.001 levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tstyles/image/image_comparison.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/style_library.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/video/video_file.h"
#include "data/realistic_datasets.h"

namespace {

namespace fs = std::filesystem;
using tstyles::Image;
using tstyles::Scene;

constexpr int kMaxLevels = 2;
constexpr double kMaxMeanLevels = 0.05;
constexpr double kMaxFractionAboveOneLevel = 0.001;

std::optional<fs::path> findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream folders(path != nullptr ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        const fs::path candidate = fs::path(folder) / name;
        std::error_code error;
        if (!folder.empty() && fs::is_regular_file(candidate, error)) return candidate;
    }
    return std::nullopt;
}

std::string quoted(const fs::path& path) {
    std::string text = "'";
    for (const char c : path.string()) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return text + "'";
}

struct CommandResult {
    int exitCode = -1;
    std::string output;
};

CommandResult runCommand(const std::string& command) {
    CommandResult result;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return result;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), int(buffer.size()), pipe) != nullptr) result.output += buffer.data();
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

class ViewerSession : public ::testing::Test {
protected:
    void SetUp() override {
        xvfbRun_ = findProgram("xvfb-run");
        if (!xvfbRun_)
            GTEST_SKIP() << "xvfb-run is not on PATH, so the viewer cannot open a window here; install the "
                            "xvfb package (CI does) to run the viewer tests";
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        out_ = fs::path(TSTYLES_TEST_OUTPUT_DIR) / "viewer" / test->name();
        fs::remove_all(out_);
        fs::create_directories(out_);
    }

    // Runs the viewer on `input` with a script from tests/viewer/scripts in a 640x480 window.
    // `options`: more command-line options, as typed.
    CommandResult view(const fs::path& input, const std::string& script, const std::string& options = "") const {
        const fs::path scriptFile = fs::path(TSTYLES_SOURCE_DIR) / "tests/viewer/scripts" / script;
        const std::string command = "OUT=" + quoted(out_) + " timeout 100 " + quoted(*xvfbRun_) +
                                    " -a -s '-screen 0 1024x768x24' " + quoted(TSTYLES_EXECUTABLE) + " view " +
                                    quoted(input) + " --size 640x480 --no-vsync --script " + quoted(scriptFile) +
                                    (options.empty() ? "" : " " + options);
        CommandResult result = runCommand(command);
        fs::path log = out_ / "viewer.log";
        std::ofstream(log) << command << "\n" << result.output;
        return result;
    }

    Image renderHeadless(const fs::path& scene, const fs::path& image, const std::string& options = "") const {
        const CommandResult result = runCommand(quoted(TSTYLES_EXECUTABLE) + " render " + quoted(scene) + " -o " +
                                                quoted(image) + (options.empty() ? "" : " " + options));
        EXPECT_EQ(result.exitCode, 0) << result.output;
        return tstyles::readImage(image);
    }

    // The window's volume area against `tstyles render` of the scene it saved.
    // `options`: the render options that match the viewer's (--max-gpu-memory).
    void expectWindowMatchesHeadless(const fs::path& scene, const fs::path& windowImage,
                                     const std::string& options = "") const {
        const Image window = tstyles::readImage(windowImage);
        const Image headless = renderHeadless(scene, out_ / "headless.png", options);
        ASSERT_EQ(window.width, headless.width);
        ASSERT_EQ(window.height, headless.height);
        const auto difference = tstyles::compareImages(window, headless, 1);
        const bool close = difference.maxDelta <= kMaxLevels && difference.meanDelta <= kMaxMeanLevels &&
                           difference.failingFraction <= kMaxFractionAboveOneLevel;
        if (!close) tstyles::writeImage(tstyles::differenceImage(window, headless, 16.0f), out_ / "difference.png");
        EXPECT_TRUE(close) << tstyles::describe(difference) << " (window " << windowImage << ", headless "
                           << (out_ / "headless.png") << ", difference x16 " << (out_ / "difference.png") << ")";
    }

    static fs::path bundledScene(const std::string& name) {
        return fs::path(TSTYLES_SOURCE_DIR) / "data/scenes" / name;
    }

    std::optional<fs::path> xvfbRun_;
    fs::path out_;
};

TEST_F(ViewerSession, GroupDragMovesTheFocusToTimeStepSix) {
    const fs::path opened = bundledScene("figure1-focus-step3.json");
    const CommandResult run = view(opened, "group_drag.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;

    const Scene before = tstyles::loadScene(opened);
    const Scene after = tstyles::loadScene(out_ / "focus-step6.json");
    // The focus is the opaque time-step: 3 before, 6 after.
    EXPECT_EQ(before.indexTstf.atStep(3).opacity, 1.0);
    EXPECT_EQ(after.indexTstf.atStep(6).opacity, 1.0);
    EXPECT_LT(after.indexTstf.atStep(3).opacity, 0.1);
    // Exactly the focus nodes (time-steps 2 to 4) moved, by three whole time-steps, as one group;
    // everything else is as it was.
    Scene expected = before;
    for (auto& node : expected.indexTstf.curve.opacity)
        if (node.at >= 2.0 && node.at <= 4.0) node = {node.at + 3.0, node.opacity, 1};
    for (auto& node : expected.indexTstf.curve.color)
        if (node.at >= 2.0 && node.at <= 4.0) {
            node.at += 3.0;
            node.group = 1;
        }
    expected.indexTstf.curve.sortNodes();
    EXPECT_EQ(after.indexTstf, expected.indexTstf);
    EXPECT_EQ(after.stf, before.stf);
    EXPECT_EQ(after.camera, before.camera);
    if (fs::exists(bundledScene("figure1-focus-step6.json"))) {
        EXPECT_EQ(after.indexTstf, tstyles::loadScene(bundledScene("figure1-focus-step6.json")).indexTstf)
            << "the bundled right half of Figure 1 differs from the group moved in the window";
    }

    expectWindowMatchesHeadless(out_ / "focus-step6.json", out_ / "window.png");
}

TEST_F(ViewerSession, OrbitDragChangesTheCameraAndRendersHeadlessAlike) {
    const CommandResult run = view(bundledScene("figure1-focus-step3.json"), "orbit_drag.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;

    const Scene before = tstyles::loadScene(out_ / "before.json");
    const Scene after = tstyles::loadScene(out_ / "after.json");
    EXPECT_NE(after.camera, before.camera);
    const auto& orbitBefore = std::get<tstyles::OrbitCamera>(before.camera.pose);
    const auto& orbitAfter = std::get<tstyles::OrbitCamera>(after.camera.pose);
    // 30 % of the view's width to the right turns the data right (azimuth down), 10 % of its height
    // up lowers the eye; 0.3 degrees per pixel.
    const double dx = 0.3 * after.width;
    const double dy = -0.1 * after.height;
    EXPECT_NEAR(orbitAfter.azimuthDeg - orbitBefore.azimuthDeg, -0.3 * dx, 0.5);
    EXPECT_NEAR(orbitAfter.elevationDeg - orbitBefore.elevationDeg, 0.3 * dy, 0.5);
    EXPECT_EQ(after.indexTstf, before.indexTstf);

    expectWindowMatchesHeadless(out_ / "after.json", out_ / "window.png");
}

// Lit-sphere styles read the image at a rate set by the size of a pixel: the tiles the window
// refines in must count their pixels as the frame's, or styled data would differ from headless.
TEST_F(ViewerSession, AStyledSceneRefinesToTheOnePassRender) {
    const std::vector<std::string> styles = tstyles::builtInStyleNames();
    if (styles.size() < 2) GTEST_SKIP() << "fewer than two built-in styles in the bundled data/styles";
    Scene scene = tstyles::loadScene(bundledScene("figure1-focus-step3.json"));
    for (std::size_t i = 0; i < scene.indexTstf.curve.color.size(); ++i)
        scene.indexTstf.curve.color[i].style = styles[i % styles.size()];
    tstyles::saveScene(scene, out_ / "styled.json");
    const CommandResult run = view(out_ / "styled.json", "refine_and_save.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(tstyles::loadScene(out_ / "shown.json").indexTstf, scene.indexTstf);
    expectWindowMatchesHeadless(out_ / "shown.json", out_ / "window.png");
}

// --max-gpu-memory in the viewer stores the series as `render` does under the same budget: the
// Figure 1 series (5.0 MiB at 16 bits; 2.5 MiB at 8) in 2 MiB is uploaded coarser, the viewer says
// so on stderr, and the window shows what `render --max-gpu-memory 2M` shows, not what the
// full-resolution render shows.
TEST_F(ViewerSession, AGpuMemoryBudgetShowsWhatRenderShowsUnderIt) {
    const CommandResult run = view(bundledScene("figure1-focus-step3.json"), "refine_and_save.txt", "--max-gpu-memory 2M");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("GPU memory budget 2.0 MiB (--max-gpu-memory)"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("resolution 1/"), std::string::npos) << run.output;

    expectWindowMatchesHeadless(out_ / "shown.json", out_ / "window.png", "--max-gpu-memory 2M");
    const Image full = renderHeadless(out_ / "shown.json", out_ / "full-resolution.png");
    const auto difference = tstyles::compareImages(tstyles::readImage(out_ / "window.png"), full, 1);
    EXPECT_GT(difference.maxDelta, kMaxLevels) << "the budget changed nothing: " << tstyles::describe(difference);
}

TEST_F(ViewerSession, UndoRestoresThePreviousSceneExactly) {
    const CommandResult run = view(bundledScene("figure1-focus-step3.json"), "undo_redo.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto scene = [&](const char* name) { return tstyles::loadScene(out_ / name); };

    const Scene opened = scene("0-opened.json");
    const Scene groupMoved = scene("1-group-moved.json");
    const Scene stfEdited = scene("2-stf-edited.json");
    const Scene orbited = scene("3-orbited.json");
    // Each edit changed what it should and nothing else.
    EXPECT_NE(groupMoved.indexTstf, opened.indexTstf);
    EXPECT_EQ(groupMoved.indexTstf.atStep(5).opacity, 1.0);
    EXPECT_EQ(groupMoved.stf, opened.stf);
    EXPECT_NE(stfEdited.stf, groupMoved.stf);
    EXPECT_EQ(stfEdited.indexTstf, groupMoved.indexTstf);
    EXPECT_NE(orbited.camera, stfEdited.camera);

    EXPECT_EQ(scene("4-undo-orbit.json"), stfEdited);
    EXPECT_EQ(scene("5-undo-stf.json"), groupMoved);
    EXPECT_EQ(scene("6-redo-stf.json"), stfEdited);
}

TEST_F(ViewerSession, BadScenesShowAnErrorAndKeepTheOpenScene) {
    std::ofstream(out_ / "broken.json") << "{\"dataset\": \"../superellipsoid/series.json\", \"image\": {\"width\": \"wide\"}}";
    Scene missingStyle = tstyles::loadScene(bundledScene("figure1-focus-step3.json"));
    missingStyle.indexTstf.curve.color.front().style = "no-such-folder/missing-style.png";
    tstyles::saveScene(missingStyle, out_ / "missing-style.json");
    // Issue 43: a style name too long for the file system is a bad scene like the others.
    missingStyle.indexTstf.curve.color.front().style = std::string(5000, 'a');
    tstyles::saveScene(missingStyle, out_ / "long-style-name.json");
    const CommandResult run = view(bundledScene("figure1-focus-step3.json"), "bad_scene.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("image.width: expected a number"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("missing-style.png"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("long-style-name.json: tstf.index.color[0].style: the name is too long for the file system "
                              "(5000 characters)"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(tstyles::loadScene(out_ / "after.json"), tstyles::loadScene(out_ / "before.json"));
}

// Issue 39: a folder and a file dragged onto the window from outside (a file manager's drop, made
// through the X server by tests/viewer/xdnd_drop.cpp) open as File > Open opens them.
TEST_F(ViewerSession, DroppedFolderAndFileOpen) {
    const fs::path folder = fs::path(TSTYLES_SOURCE_DIR) / "data/hurricane";
    const fs::path file = out_ / "ocean eddy.nc";  // a CF NetCDF; the space must survive the URI
    tstyles::testdata::writeOceanEddy(file);
    const fs::path script = fs::path(TSTYLES_SOURCE_DIR) / "tests/viewer/scripts/drop_files.txt";
    const std::string viewer = quoted(TSTYLES_EXECUTABLE) + " view " +
                               quoted(bundledScene("figure1-focus-step3.json")) +
                               " --size 640x480 --no-vsync --script " + quoted(script);
    const std::string drop =
        quoted(TSTYLES_XDND_DROP) + " --title 'Temporal Styles - ' --timeout 80 " + quoted(folder) + " " + quoted(file);
    const std::string both = viewer + " & viewer=$!; " + drop + "; drop=$?; wait $viewer; echo \"exit codes: viewer $? drop $drop\"";
    const std::string command = "timeout 100 " + quoted(*xvfbRun_) + " -a -s '-screen 0 1024x768x24' sh -c " +
                                quoted(fs::path(both));
    const CommandResult run = runCommand(command);
    std::ofstream(out_ / "viewer.log") << command << "\n" << run.output;
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("exit codes: viewer 0 drop 0"), std::string::npos) << run.output;
    // The viewer says what it opened, in the order dropped; the helper saw the title change each time.
    const std::size_t openedFolder = run.output.find("opened " + folder.string() + "\n");
    const std::size_t openedFile = run.output.find("opened " + file.string() + "\n");
    EXPECT_NE(openedFolder, std::string::npos) << run.output;
    EXPECT_NE(openedFile, std::string::npos) << run.output;
    EXPECT_LT(openedFolder, openedFile) << run.output;
    EXPECT_NE(run.output.find("dropped " + file.string() + ": the window is now titled 'Temporal Styles - "),
              std::string::npos)
        << run.output;
}

}  // namespace

namespace {

TEST_F(ViewerSession, RecordedKeysExportTheMovieThatAnimateMakes) {
    // The bundled scene at 128x128, in the output folder: the movie goes beside it.
    Scene scene = tstyles::loadScene(bundledScene("figure1-focus-step3.json"));
    scene.width = scene.height = 128;
    tstyles::saveScene(scene, out_ / "scene.json");
    const CommandResult run = view(out_ / "scene.json", "record_movie.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;

    // Two keys a second apart: 25 frames at 24 fps, the orbit's azimuth moving between them.
    const Scene recorded = tstyles::loadScene(out_ / "recorded.json");
    ASSERT_EQ(recorded.animation.frames, 25);
    EXPECT_EQ(recorded.animation.framesPerSecond, 24);
    const auto azimuth = std::find_if(recorded.animation.tracks.begin(), recorded.animation.tracks.end(),
                                      [](const tstyles::AnimationTrack& track) {
                                          return std::get<tstyles::ValueTrackTarget>(track.target).path ==
                                                 "camera.orbit.azimuth_deg";
                                      });
    ASSERT_NE(azimuth, recorded.animation.tracks.end());
    ASSERT_EQ(azimuth->keys.size(), 2u);
    EXPECT_EQ(azimuth->keys[0].value, std::get<tstyles::OrbitCamera>(scene.camera.pose).azimuthDeg);
    EXPECT_NE(azimuth->keys[1].value, azimuth->keys[0].value);

    const fs::path movie = out_ / "scene.mp4";
    ASSERT_TRUE(fs::exists(movie)) << run.output;
    const tstyles::VideoInfo info = tstyles::probeVideo(movie);
    EXPECT_EQ(info.frameCount, 25);
    EXPECT_EQ(info.width, 128);
    EXPECT_EQ(info.height, 128);
    EXPECT_DOUBLE_EQ(info.framesPerSecond, 24.0);

    // Frame 12 of the movie is `render --frame 12` of the saved scene, within H.264's loss: a mean
    // of 2/255 per channel (CRF 18 on 4:2:0 colour at 128x128).
    const CommandResult rendered = runCommand(quoted(TSTYLES_EXECUTABLE) + " render " + quoted(out_ / "recorded.json") +
                                              " --frame 12 --width 128 --height 128 -o " + quoted(out_ / "frame12.png"));
    ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
    const Image expected = tstyles::readImage(out_ / "frame12.png");
    const Image decoded = tstyles::readVideoFrames(movie).at(12);
    double sum = 0.0;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c) sum += std::abs(decoded.at(x, y)[c] - expected.at(x, y)[c]);
    EXPECT_LT(sum / (128.0 * 128.0 * 3.0), 2.0 / 255.0);
}

}  // namespace

namespace {

// The fields of one CSV line (RFC 4180: quoted fields may hold commas and doubled quotes).
std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::stringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) rows.push_back(csvFields(line));
    return rows;
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Issue 55: a ctrl+click on the picture of a CF forecast (pressure levels counting down, shown as a
// map with vertical exaggeration) pins a probe; the panel's CSV holds, for the place it names in the
// file's coordinates, the values `tstyles probe --at` reads there; probes are saved with the scene,
// removed in the panel, and brought back by undo.
TEST_F(ViewerSession, AProbeClickedOnAForecastHoldsWhatTheCommandLineReads) {
    const fs::path forecast = out_ / "forecast.nc";
    tstyles::testdata::writeRegionalForecast(forecast);
    const CommandResult run = view(forecast, "probe_forecast.txt");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Scene one = tstyles::loadScene(out_ / "1-one-probe.json");
    const Scene two = tstyles::loadScene(out_ / "2-two-probes.json");
    ASSERT_EQ(one.probes.size(), 1u) << run.output;
    ASSERT_EQ(two.probes.size(), 2u) << run.output;
    EXPECT_EQ(two.probes[0], one.probes[0]);
    const Scene removed = tstyles::loadScene(out_ / "3-first-removed.json");
    ASSERT_EQ(removed.probes.size(), 1u);
    EXPECT_EQ(removed.probes[0], two.probes[1]);
    EXPECT_EQ(tstyles::loadScene(out_ / "4-undone.json").probes, two.probes);

    const auto rows = csvRows(readFile(out_ / "probes.csv"));
    ASSERT_EQ(rows.size(), 8u) << readFile(out_ / "probes.csv");  // the header and 7 time-steps
    ASSERT_EQ(rows[0].size(), 4u);
    for (std::size_t probe = 0; probe < 2; ++probe) {
        // "probe 1 at (-95.1, 40.2, 612.5)": the place as `probe --at` takes it.
        const std::string& header = rows[0][2 + probe];
        const std::size_t open = header.find('(');
        ASSERT_EQ(header.rfind("probe " + std::to_string(probe + 1) + " at (", 0), 0u) << header;
        std::string place = header.substr(open + 1, header.size() - open - 2);
        place.erase(std::remove(place.begin(), place.end(), ' '), place.end());
        const CommandResult cli =
            runCommand(quoted(TSTYLES_EXECUTABLE) + " probe " + quoted(forecast) + " --at " + place + " --csv");
        ASSERT_EQ(cli.exitCode, 0) << cli.output;
        const auto cliRows = csvRows(cli.output);
        ASSERT_EQ(cliRows.size(), rows.size()) << cli.output;
        int present = 0;
        for (std::size_t row = 1; row < rows.size(); ++row) {
            EXPECT_EQ(rows[row][0], cliRows[row][0]);  // the times
            EXPECT_EQ(rows[row][1], cliRows[row][1]);  // their labels
            const std::string& window = rows[row][2 + probe];
            const std::string& command = cliRows[row][2];
            ASSERT_EQ(window.empty(), command.empty()) << "row " << row << " of probe " << probe + 1;
            if (window.empty()) continue;
            ++present;
            // The window samples the series turned for display, the command line as read: the
            // same trilinear weights up to rounding, then float32 (7 digits).
            EXPECT_NEAR(std::stod(window), std::stod(command), 1e-6 * std::max(1e-30, std::abs(std::stod(command))))
                << "row " << row << " of probe " << probe + 1;
        }
        EXPECT_EQ(present, 7) << "probe " << probe + 1 << " at " << place;
    }
}

}  // namespace
