// The frame loop: input (window and script), UI, history, progressive rendering, presentation.
#include "viewer_app.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include <imgui.h>

#include "probe_panel.h"
#include "side_panel.h"
#include "volume_picking.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/gl/gl_api.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/gpu_memory_limits.h"
#include "tstyles/scene/scene_file.h"
#include "viewer_menu.h"
#include "window_capture.h"

namespace tstyles::viewer {
namespace {

ViewerDocument openInitialDocument(const ViewerOptions& options) {
    ViewerDocument document = options.inputs.empty()
                                  ? openDocument(defaultViewerInput(options.dataDirectory), nullptr)
                                  : openDocument(options.inputs, nullptr, options.readOptions);
    if (options.adjustFirstScene) options.adjustFirstScene(document.scene, *document.series, !document.sceneFile);
    return document;
}

std::optional<ScriptPlayer> loadScript(const ViewerOptions& options) {
    if (!options.script) return std::nullopt;
    return ScriptPlayer(loadInputScript(*options.script), *options.script);
}

// An idle viewer sleeps until input arrives, but ImGui needs a few frames after an event to settle
// hover and focus states.
constexpr int kSettleFrames = 3;
constexpr double kIdleWaitSeconds = 0.5;

}  // namespace

int runViewer(const ViewerOptions& options) {
    ViewerApp app(options);
    return app.run();
}

ViewerApp::ViewerApp(const ViewerOptions& options)
    : options_(options),
      document_(openInitialDocument(options)),
      script_(loadScript(options)),
      window_(options.windowSize, "Temporal Styles", glDebugOutputRequested(), options.vsync),
      platform_(window_.handle()),
      renderer_(ShaderLibrary::fromEnvironment(options.shaderDirectory)),
      history_(document_.scene),
      lastRenderable_(document_.scene),
      savedScene_(document_.scene) {
    uploadSeries(*document_.series);
    if (options.inputs.size() == 1) recentFiles_.remember(options.inputs.front());
}

void ViewerApp::uploadSeries(const Series& series) {
    const GpuMemoryLimits limits =
        gpuMemoryLimitsFor(series, options_.maxGpuMemoryBytes, options_.readOptions.maxMemoryBytes);
    const GpuResidency residency = renderer_.setSeries(series, limits);
    gpuStorageChanges_ = residencyChanges(series, residency);
    if (options_.maxGpuMemoryBytes || residency.changed())
        std::cerr << "tstyles: " << residencyText(series, limits, residency) << std::endl;
}

int ViewerApp::run() {
    while (!quit_) {
        const bool idle = !script_ && !time_.playing && frame_.refined() && !screenshotPath_ && settleFrames_ == 0 &&
                          window_.events().empty();
        if (idle)
            window_.waitEvents(kIdleWaitSeconds);
        else
            window_.pollEvents();
        settleFrames_ = window_.events().empty() ? std::max(settleFrames_ - 1, 0) : kSettleFrames;
        frame();
        if (script_ && script_->finished()) script_.reset();
        if (window_.closeRequested()) {
            window_.cancelClose();
            requestQuit();
        }
    }
    return 0;
}

void ViewerApp::frame() {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;
    if (script_) script_->advance(*this, window_.events(), now);
    for (const auto& path : window_.takeDroppedFiles()) openPath(path);

    platform_.newFrame(window_.events(), window_.windowSize(), window_.framebufferSize());
    anchors_.beginFrame();
    buildUi(seconds);

    const ImGuiIO& io = ImGui::GetIO();
    const bool mouseHeld = io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2];
    // Something is being dragged (camera, node, group, slider): keep previews coming, and let the
    // whole drag become one undo step.
    const bool interacting = volumeView_.interacting(now) || editors_.dragging() ||
                             (mouseHeld && ImGui::IsAnyItemActive());
    presentVolume(interacting);
    continueMovieExport();
    if (!interacting) history_.record(document_.scene);
}

void ViewerApp::buildUi(double seconds) {
    const MenuState menu{history_.canUndo() || !(document_.scene == history_.latest()), history_.canRedo(),
                         !editors_.focused().selection().empty(), time_.playing, recentFiles_.existing()};
    std::optional<std::filesystem::path> openRecent;
    const float menuHeight = drawMainMenu(menu, commands_, openRecent);
    if (openRecent) openPath(*openRecent);
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    layout_ = layoutViewer({display.x, display.y}, menuHeight, !document_.scene.probes.empty());

    SidePanelState side{document_.scene,
                        *document_.series,
                        document_.timeLabels,
                        time_,
                        {renderer_.seriesTextureBytes(), renderer_.gradientTextureBytes(),
                         renderer_.frameTextureBytes(), gpuStorageChanges_},
                        0.5 * document_.series->finestSpacing(),
                        animation_};
    drawSidePanel(layout_.sidePanel, side, commands_, anchors_);
    editors_.draw(document_.scene, *document_.series, document_.timeLabels, *document_.histogram, layout_, anchors_);
    drawVolumeArea();
    drawProbePanel();

    collectShortcuts(commands_);
    for (const ViewerCommand command : ViewerCommands(std::exchange(commands_, {}))) execute(command);
    if (const auto choice = fileDialog_.draw()) handleFileChoice(*choice);
    errorDialog_.draw();
    switch (quitDialog_.draw(document_.sceneFile.has_value())) {
        case QuitDialog::Answer::SaveAndQuit:
            execute(ViewerCommand::Save);
            quit_ = !errorDialog_.visible();
            break;
        case QuitDialog::Answer::Quit:
            quit_ = true;
            break;
        default:
            break;
    }
    updateTitle();
    time_.advance(seconds, int(document_.series->size()));
}

void ViewerApp::drawVolumeArea() {
    const Bounds bounds = document_.series->worldBounds();
    if (const auto pixel = volumeView_.handleInput(layout_.volume, framebufferScale(), document_.scene.camera, bounds,
                                                   frameSize(), anchors_)) {
        pinProbeUnder(*pixel);
    }
    VolumeOverlay overlay;
    overlay.progress = frame_.progress();
    overlay.refined = frame_.refined();
    overlayShowedRefined_ = overlay.refined;
    overlay.previewDivisor = frame_.previewDivisor();
    overlay.framesPerSecond = statistics_.framesPerSecond();
    overlay.refinementSeconds = frame_.lastRefinementSeconds();
    const std::vector<ProbeCurve>& curves =
        probeCurves_.update(document_.scene.probes, document_.series, document_.frame);
    for (std::size_t index = 0; index < curves.size(); ++index)
        overlay.probes.push_back({curves[index].shown, probeColour(index), int(index + 1)});
    overlay.note = time_.solo ? "showing one time-step alone (not saved in the scene)" : probeNote_;
    if (animation_.previewing && !time_.solo) overlay.note = "previewing the animation (the scene is unchanged)";
    overlay.annotated = document_.scene.annotations.any();
    volumeView_.drawOverlay(layout_.volume, overlay, document_.scene.camera, bounds, frameSize());
    try {
        annotationOverlay_.draw(layout_.volume, frameSize(), shownScene(), *document_.series, document_.frame);
    } catch (const InputError& error) {
        document_.scene.annotations = {};  // e.g. the font is missing: say so once, then draw without
        errorDialog_.show(error.what());
    }
}

void ViewerApp::pinProbeUnder(glm::dvec2 pixel) {
    Scene& scene = document_.scene;
    if (scene.probes.size() >= kMaxProbes) {
        probeNote_ = "8 probes at most: remove one in the probe panel first";
        return;
    }
    const std::optional<glm::dvec3> place =
        probePlaceUnder(*document_.series, scene, pixel, frameSize(), renderer_.stepLengthFor(scene),
                        document_.series->finestSpacing());
    if (!place) {
        probeNote_ = "nothing shows under the pointer to probe";
        return;
    }
    scene.probes.push_back(fileCoordinatesOfShown(*document_.series, document_.frame, *place));
    probeNote_ = nullptr;
}

void ViewerApp::drawProbePanel() {
    Scene& scene = document_.scene;
    if (scene.probes.empty()) return;
    const ProbePanelState state{probeCurves_.update(scene.probes, document_.series, document_.frame),
                                *document_.series, scene, document_.timeLabels, time_.step};
    const ProbePanelRequests requests = viewer::drawProbePanel(layout_.probePanel, state, anchors_);
    if (requests.exportCsv) fileDialog_.open(FilePurpose::ExportProbes, dialogFolder(), "probes.csv");
    if (requests.remove && *requests.remove < scene.probes.size())
        scene.probes.erase(scene.probes.begin() + std::ptrdiff_t(*requests.remove));
    if (requests.clear) scene.probes.clear();
}

void ViewerApp::exportProbes(const std::filesystem::path& path) {
    if (document_.scene.probes.empty())
        throwInputError(path, "", "no probes to export: ctrl+click the picture to pin one first");
    requireOutputFile(PathSource{}, path, "CSV file");
    const std::vector<ProbeCurve>& curves =
        probeCurves_.update(document_.scene.probes, document_.series, document_.frame);
    std::ostringstream text;
    writeProbeCsv(text, probeColumns(curves, *document_.series, document_.timeLabels));
    writeFileAtomically(path, text.str());
    std::cout << "wrote " << curves.size() << " probe" << (curves.size() == 1 ? "" : "s") << " to " << path.string()
              << std::endl;
}

void ViewerApp::presentVolume(bool interacting) {
    const FrameWork work = updateFrame(interacting);
    const glm::ivec2 framebuffer = window_.framebufferSize();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebuffer.x, framebuffer.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    frame_.present(frameOffset());
    takeScreenshotIfDue(false);
    platform_.render();
    takeScreenshotIfDue(true);
    window_.swapBuffers();
    statistics_.addFrame(std::chrono::duration<double>(Clock::now() - lastFrame_).count(), work == FrameWork::Preview,
                         work == FrameWork::Refinement);
}

FrameWork ViewerApp::updateFrame(bool interacting) {
    try {
        const FrameWork work = frame_.update(renderer_, shownScene(), document_.series->worldBounds(), frameSize(),
                                             time_.soloTimeStep(), interacting);
        if (work == FrameWork::Preview) lastRenderable_ = document_.scene;
        return work;
    } catch (const InputError& error) {
        if (animation_.previewing) {  // a frame of the animation the series cannot show
            animation_.previewing = false;
            errorDialog_.show(error.what());
            frame_.invalidate();
            return FrameWork::None;
        }
        if (document_.scene == lastRenderable_) throw;  // nothing better to go back to
        errorDialog_.show(error.what());
        document_.scene = lastRenderable_;
        frame_.invalidate();
        return FrameWork::None;
    }
}

void ViewerApp::requestScreenshot(const std::filesystem::path& path, bool wholeWindow) {
    screenshotPath_ = path;
    screenshotOfWindow_ = wholeWindow;
}

void ViewerApp::takeScreenshotIfDue(bool wholeWindow) {
    if (!screenshotPath_ || !frame_.refined() || screenshotOfWindow_ != wholeWindow) return;
    if (wholeWindow && !overlayShowedRefined_) return;
    const std::filesystem::path path = *std::exchange(screenshotPath_, std::nullopt);
    const glm::ivec2 offset = wholeWindow ? glm::ivec2(0) : frameOffset();
    const glm::ivec2 size = wholeWindow ? window_.framebufferSize() : frameSize();
    try {
        writeImage(captureWindowRegion(offset, size), path);
        std::cout << "wrote screenshot " << path.string() << " (" << size.x << "x" << size.y << ")" << std::endl;
    } catch (const InputError& error) {
        if (script_) throw;
        errorDialog_.show(error.what());
    }
}

void ViewerApp::stopMeasurement() {
    std::cout << FrameStatistics::describe(statistics_.stop()) << " at " << frameSize().x << "x" << frameSize().y
              << " volume pixels, previews at 1/" << frame_.previewDivisor() << ", tiles 1/" << frame_.tileDivisor()
              << " of each side" << std::endl;
}

std::optional<glm::vec2> ViewerApp::resolveAnchor(const std::string& name,
                                                  const std::optional<glm::dvec2>& parameters) const {
    return anchors_.resolve(name, parameters);
}

glm::vec2 ViewerApp::framebufferScale() const {
    const glm::ivec2 window = window_.windowSize();
    const glm::ivec2 framebuffer = window_.framebufferSize();
    if (window.x <= 0 || window.y <= 0) return glm::vec2(1.0f);
    return glm::vec2(framebuffer) / glm::vec2(window);
}

glm::ivec2 ViewerApp::frameSize() const {
    const glm::vec2 scale = framebufferScale();
    const glm::ivec2 min = glm::ivec2(glm::round(layout_.volume.min * scale));
    const glm::ivec2 max = glm::ivec2(glm::round(layout_.volume.max * scale));
    return glm::max(max - min, glm::ivec2(0));
}

glm::ivec2 ViewerApp::frameOffset() const {
    const glm::vec2 scale = framebufferScale();
    const glm::ivec2 min = glm::ivec2(glm::round(layout_.volume.min * scale));
    return {min.x, window_.framebufferSize().y - min.y - frameSize().y};
}

}  // namespace tstyles::viewer
