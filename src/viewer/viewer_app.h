// The viewer application: owns the window, the renderer, the open document and the panels, runs
// the frame loop, and carries out the commands the UI and scripts ask for.
#pragma once

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animation_state.h"
#include "annotation_overlay.h"
#include "editor_panels.h"
#include "frame_statistics.h"
#include "imgui_platform.h"
#include "movie_export.h"
#include "progressive_frame.h"
#include "recent_files.h"
#include "scene_history.h"
#include "script_player.h"
#include "time_control.h"
#include "tstyles/render/renderer.h"
#include "ui_anchors.h"
#include "viewer.h"
#include "viewer_commands.h"
#include "viewer_dialogs.h"
#include "viewer_document.h"
#include "viewer_layout.h"
#include "viewer_window.h"
#include "probe_curves.h"
#include "volume_view.h"

namespace tstyles::viewer {

class ViewerApp final : public ScriptHost {
public:
    explicit ViewerApp(const ViewerOptions& options);
    int run();

    // ScriptHost: what test scripts may ask of the application.
    std::optional<glm::vec2> resolveAnchor(const std::string& name,
                                           const std::optional<glm::dvec2>& parameters) const override;
    std::string anchorNames() const override { return anchors_.currentNames(); }
    // A movie being exported keeps the view from refining: scripts wait for the export too.
    bool viewRefined() const override { return frame_.refined() && !movieExport_; }
    void openFromScript(const std::filesystem::path& path) override { openPath(path); }
    void saveSceneFromScript(const std::filesystem::path& path) override { saveTo(path); }
    void exportProbesFromScript(const std::filesystem::path& path) override { exportProbes(path); }
    void requestScreenshot(const std::filesystem::path& path, bool wholeWindow) override;
    bool screenshotPending() const override { return screenshotPath_.has_value(); }
    void startMeasurement(const std::string& label) override { statistics_.start(label); }
    void stopMeasurement() override;
    void quitFromScript() override { quit_ = true; }

private:
    using Clock = std::chrono::steady_clock;

    void frame();
    void buildUi(double seconds);
    void drawVolumeArea();
    // Pins a probe where the picture shows the data under `pixel` (volume_picking.h), or says why not.
    void pinProbeUnder(glm::dvec2 pixel);
    void drawProbePanel();
    void presentVolume(bool interacting);
    // Brings the progressive frame up to date; an InputError from the renderer shows the error
    // dialog and restores the last scene it accepted.
    FrameWork updateFrame(bool interacting);
    // The scene the volume shows: the document's, or its animation at the previewed frame.
    Scene shownScene() const;
    void addKey();
    void startMovieExport();
    // One frame of a running export per UI frame, so the window stays responsive.
    void continueMovieExport();
    // Called after the volume is drawn (wholeWindow false) and after the panels (true).
    void takeScreenshotIfDue(bool wholeWindow);

    // Quits, or asks first when there are unsaved changes (never while a script runs).
    void requestQuit();
    void updateTitle();

    void execute(ViewerCommand command);
    void executeEdit(ViewerCommand command);
    void handleFileChoice(const FileChoice& choice);
    // Opens a scene or dataset; a failure shows the error dialog and keeps the current scene.
    void openPath(const std::filesystem::path& path);
    void adopt(ViewerDocument next);
    // Uploads the series within the GPU memory limits (ViewerOptions::maxGpuMemoryBytes) and keeps
    // what had to change for the dataset section; says so on stderr as `render` does.
    void uploadSeries(const Series& series);
    // Writes the scene as shown (image size = the volume area). Throws InputError.
    void saveTo(const std::filesystem::path& path);
    // Writes the probes' curves as CSV (probe_curves.h), whole or not at all. Throws InputError.
    void exportProbes(const std::filesystem::path& path);
    std::filesystem::path dialogFolder() const;

    // The volume area in framebuffer pixels: its size, and its offset from the bottom left.
    glm::ivec2 frameSize() const;
    glm::ivec2 frameOffset() const;
    glm::vec2 framebufferScale() const;

    ViewerOptions options_;
    // Opened and read first: a bad input or script fails before any window appears.
    ViewerDocument document_;
    std::optional<ScriptPlayer> script_;
    ViewerWindow window_;
    ImGuiPlatform platform_;
    Renderer renderer_;
    SceneHistory history_;
    ProgressiveFrame frame_;
    EditorPanels editors_;
    VolumeView volumeView_;
    TimeControl time_;
    AnimationState animation_;
    std::optional<MovieExport> movieExport_;
    AnnotationOverlay annotationOverlay_;
    ProbeCurves probeCurves_;
    UiAnchors anchors_;
    FileDialog fileDialog_;
    // Scripted sessions (tests) leave the user's list alone.
    RecentFiles recentFiles_{options_.script ? std::filesystem::path()
                                             : recentFilesLocation(std::getenv("XDG_STATE_HOME"), std::getenv("HOME"))};
    ErrorDialog errorDialog_;
    QuitDialog quitDialog_;
    FrameStatistics statistics_;
    ViewerLayout layout_;
    ViewerCommands commands_;
    std::optional<std::filesystem::path> screenshotPath_;
    bool screenshotOfWindow_ = false;
    bool quit_ = false;
    int settleFrames_ = 0;
    Clock::time_point lastFrame_ = Clock::now();
    // Why the last ctrl+click pinned no probe; cleared by the next pin.
    const char* probeNote_ = nullptr;
    // What the overlay (drawn before this frame's rendering) said: a window screenshot waits until
    // the overlay too shows the finished frame.
    bool overlayShowedRefined_ = false;
    // The last scene the renderer accepted: an edit it refuses (a style image that cannot be read)
    // is taken back to this.
    Scene lastRenderable_;
    // The scene as opened or last saved: anything else is an unsaved change.
    Scene savedScene_;
    std::string title_;
    // How the shown series is stored on the GPU where the memory limits changed it (empty: as read).
    std::vector<std::string> gpuStorageChanges_;
};

}  // namespace tstyles::viewer
